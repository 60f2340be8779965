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

// The <ForceSet> of a ForceSet file, with its <defaults> given to the objects that lack them
// (OpenSim makes each object as a copy of its class's default object, then reads it).
pugi::xml_node FindForceSet(const internal::XmlDocument& doc) {
  pugi::xml_node set = doc.root();
  if (std::string_view(set.name()) == "OpenSimDocument") set = set.child("ForceSet");
  if (!set || std::string_view(set.name()) != "ForceSet") {
    doc.Fail(doc.root(), "",
             "not a ForceSet file (root element <" + std::string(doc.root().name()) + ">)");
  }
  const pugi::xml_node defaults = set.child("defaults");
  for (pugi::xml_node object : internal::ObjectsOf(set)) {
    const pugi::xml_node fallback = defaults.child(object.name());
    for (const pugi::xml_node& property : fallback.children()) {
      if (property.type() == pugi::node_element && !object.child(property.name())) {
        object.append_copy(property);
      }
    }
  }
  return set;
}

// OpenSim reads a document without an OpenSimDocument root as format 10500 (before 1.6).
constexpr int kUnwrappedDocumentVersion = 10500;

// Appends (or, with `replace`, substitutes) the forces of the ForceSet files, each with its own
// file's format version (a bare <ForceSet> is 10500, as in OpenSim).
void ReadForceSetFiles(internal::ReadContext& ctx, const ForceSetFiles& force_sets) {
  if (force_sets.replace) ctx.spec().forces.clear();
  const internal::XmlDocument& model_doc = ctx.doc();
  for (const std::string& file : force_sets.files) {
    const internal::XmlDocument doc = internal::XmlDocument::Load(file);
    ctx.SwitchDocument(doc);
    const int version = std::string_view(doc.root().name()) == "OpenSimDocument"
                            ? ReadVersion(doc, doc.root(), ctx.spec())
                            : kUnwrappedDocumentVersion;
    internal::ReadForceSet(ctx, FindForceSet(doc), version);
    ctx.SwitchDocument(model_doc);
  }
}

model::ModelSpec ReadDocument(const internal::XmlDocument& doc,
                              const ForceSetFiles& force_sets = {}) {
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
  ReadForceSetFiles(ctx, force_sets);
  internal::ReadOtherComponents(ctx, model);
  internal::ValidateSpec(ctx, model);
  return spec;
}

}  // namespace

model::ModelSpec ReadOsim(const std::string& file) {
  return ReadDocument(internal::XmlDocument::Load(file));
}

model::ModelSpec ReadOsim(const std::string& file, const ForceSetFiles& force_sets) {
  return ReadDocument(internal::XmlDocument::Load(file), force_sets);
}

model::ModelSpec ReadOsimString(std::string text, const std::string& file) {
  return ReadDocument(internal::XmlDocument::Parse(std::move(text), file));
}

}  // namespace sinew::io
