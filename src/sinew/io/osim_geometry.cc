// Visual geometry: 4.x attached_geometry (Mesh, Sphere, Cylinder, Brick, ...) and 3.x
// VisibleObject (geometry_files, or a GeometrySet of DisplayGeometry) with transform, scale and
// appearance.
#include <sinew/io/internal/osim_context.h>

#include <sstream>

namespace sinew::io::internal {
namespace {

// 3.x `transform`: body-fixed XYZ angles then translation (6 numbers).
Transform ReadSixTransform(const XmlDocument& doc, const pugi::xml_node& parent,
                           const std::string& component) {
  pugi::xml_node node = parent.child("transform");
  if (!node) return Transform::Identity();
  std::vector<double> v = doc.ReadNumbers(node, component, 6);
  return MakeTransform(Vec3(v[0], v[1], v[2]), Vec3(v[3], v[4], v[5]));
}

void ReadAppearance(const XmlDocument& doc, const pugi::xml_node& geometry,
                    const std::string& component, model::GeometrySpec& spec) {
  pugi::xml_node appearance = geometry.child("Appearance");
  if (!appearance) return;
  spec.visible = ReadBoolOr(doc, appearance, "visible", component, true);
  spec.opacity = ReadDoubleOr(doc, appearance, "opacity", component, 1.0);
  spec.color = ReadVec3Or(doc, appearance, "color", component, Vec3::Ones());
}

}  // namespace

void ReadAttachedGeometry(ReadContext& ctx, const pugi::xml_node& owner,
                          const std::string& owner_path, const std::string& component) {
  const XmlDocument& doc = ctx.doc();
  for (pugi::xml_node geometry : ObjectsOf(owner.child("attached_geometry"))) {
    model::GeometrySpec spec;
    spec.name = NameOf(geometry);
    spec.type = geometry.name();
    const std::string path = owner_path + "/" + spec.name;
    const std::string where = component + "/" + spec.name;
    pugi::xml_node socket = geometry.child("socket_frame");
    std::string socket_text = socket ? std::string(XmlDocument::Text(socket)) : "..";
    if (socket_text.empty()) socket_text = "..";
    const FrameEntry* frame = nullptr;
    spec.frame = ctx.ResolveFrame(path, socket_text, socket ? socket : geometry, where, &frame);
    spec.body = frame->body;
    spec.X_BG = frame->X_BF;
    spec.mesh_file = TextOf(geometry, "mesh_file");
    spec.scale_factors = ReadVec3Or(doc, geometry, "scale_factors", where, Vec3::Ones());
    ReadAppearance(doc, geometry, where, spec);
    spec.dimensions = ReadNumericLeaves(doc, geometry, where, {"scale_factors"});
    ctx.spec().bodies[spec.body].geometry.push_back(std::move(spec));
  }
}

void ReadVisibleObject(ReadContext& ctx, const pugi::xml_node& visible, int body,
                       const std::string& frame_path, const std::string& component) {
  const XmlDocument& doc = ctx.doc();
  const Vec3 scale = ReadVec3Or(doc, visible, "scale_factors", component, Vec3::Ones());
  const Transform X_BV = ReadSixTransform(doc, visible, component);
  std::vector<model::GeometrySpec>& out = ctx.spec().bodies[body].geometry;
  // geometry_files: a list of mesh file names sharing the object's transform and scale.
  std::istringstream files(TextOf(visible, "geometry_files"));
  std::string file;
  while (files >> file) {
    model::GeometrySpec spec;
    spec.name = file;
    spec.type = "Mesh";
    spec.body = body;
    spec.frame = frame_path;
    spec.X_BG = X_BV;
    spec.mesh_file = file;
    spec.scale_factors = scale;
    out.push_back(std::move(spec));
  }
  // GeometrySet of DisplayGeometry (3.x after 2.x): each with its own transform and scale.
  for (pugi::xml_node display : ObjectsOf(visible.child("GeometrySet"))) {
    model::GeometrySpec spec;
    spec.name = NameOf(display);
    spec.type = "Mesh";
    spec.body = body;
    spec.frame = frame_path;
    spec.mesh_file = TextOf(display, "geometry_file");
    if (spec.name.empty()) spec.name = spec.mesh_file;
    spec.X_BG = X_BV * ReadSixTransform(doc, display, component);
    spec.scale_factors =
        scale.cwiseProduct(ReadVec3Or(doc, display, "scale_factors", component, Vec3::Ones()));
    spec.color = ReadVec3Or(doc, display, "color", component, Vec3::Ones());
    spec.opacity = ReadDoubleOr(doc, display, "opacity", component, 1.0);
    spec.visible = ReadDoubleOr(doc, display, "display_preference", component, 4) != 0;
    out.push_back(std::move(spec));
  }
}

}  // namespace sinew::io::internal
