// The .osim reader's entry points: parse, find the model, read its parts in dependency order
// (bodies and frames, joints and coordinates, then everything that refers to them), validate.
#include <sinew/io/internal/osim_context.h>
#include <sinew/io/osim_reader.h>

#include <charconv>
#include <string_view>

namespace sinew::io {
namespace {

constexpr int kNewestKnownVersion = 40600;

int ReadVersion(const internal::XmlDocument& doc, const pugi::xml_node& root,
                model::ModelSpec& spec) {
  pugi::xml_attribute attribute = root.attribute("Version");
  if (!attribute) {
    spec.warnings.push_back({doc.Where(root), "", "OpenSimDocument has no Version; read as 4.x"});
    return 0;
  }
  const std::string_view text = attribute.value();
  int version = 0;
  auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), version);
  if (ec != std::errc() || ptr != text.data() + text.size() || version <= 0) {
    doc.Fail(root, "", "OpenSimDocument Version '" + std::string(text) + "' is not a number");
  }
  if (version > kNewestKnownVersion) {
    spec.warnings.push_back({doc.Where(root), "",
                             "format version " + std::to_string(version) +
                                 " is newer than the newest known (" +
                                 std::to_string(kNewestKnownVersion) + ")"});
  }
  return version;
}

model::ModelSpec ReadDocument(const internal::XmlDocument& doc) {
  model::ModelSpec spec;
  spec.file = doc.file();
  pugi::xml_node root = doc.root();
  pugi::xml_node model;
  const std::string_view root_tag = root.name();
  if (root_tag == "OpenSimDocument") {
    spec.version = ReadVersion(doc, root, spec);
    model = root.child("Model");
    if (!model) doc.Fail(root, "", "OpenSimDocument holds no <Model>");
  } else if (root_tag == "Model") {
    model = root;
    spec.warnings.push_back({doc.Where(root), "", "no OpenSimDocument around <Model>"});
  } else {
    doc.Fail(root, "", "not an OpenSim model: the root element is <" + std::string(root_tag) + ">");
  }
  spec.name = model.attribute("name").value();
  if (pugi::xml_node gravity = model.child("gravity")) spec.gravity = doc.ReadVec3(gravity, "/");

  internal::ReadContext ctx(doc, spec);
  internal::ReadBodies(ctx, model);
  internal::ReadJoints(ctx, model);
  ctx.ResolveAllFrames();
  internal::ReadForces(ctx, model);
  internal::ReadOtherComponents(ctx, model);
  internal::ValidateSpec(ctx, model);
  return spec;
}

}  // namespace

model::ModelSpec ReadOsim(const std::string& file) {
  return ReadDocument(internal::XmlDocument::Load(file));
}

model::ModelSpec ReadOsimString(std::string text, const std::string& file) {
  return ReadDocument(internal::XmlDocument::Parse(std::move(text), file));
}

}  // namespace sinew::io
