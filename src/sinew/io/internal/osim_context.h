// Internal to the .osim reader: the state shared by its parts while one file is read (the
// document, the spec being filled, the frame table that resolves socket paths) and small helpers.
#pragma once

#include <sinew/io/internal/xml_document.h>
#include <sinew/model/model_spec.h>

#include <pugixml.hpp>
#include <set>
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace sinew::io::internal {

/// A physical frame known by its absolute component path: a body, ground, or an offset frame
/// (4.x PhysicalOffsetFrame or a frame the 3.x upgrade creates).
struct FrameEntry {
  pugi::xml_node node;            ///< The element that defines it (for messages).
  std::string component;          ///< Component path used in messages.
  std::string parent_path;        ///< Offset frames: the parent frame's path (absolute).
  pugi::xml_node parent_node;     ///< The socket element naming the parent (for messages).
  Transform X_PF;                 ///< Offset frames: pose in the parent frame.
  int body = model::kNone;        ///< Resolved body index (kNone until resolved).
  Transform X_BF;                 ///< Resolved pose in that body's frame.
  int state = 0;                  ///< 0 unresolved, 1 being resolved, 2 resolved.
  int spec_frame = model::kNone;  ///< Index into ModelSpec::frames for offset frames.
  pugi::xml_node station_frame;   ///< A 4.5 StationDefinedFrame (else empty).
};

/// Everything the reader's parts share while reading one document.
class ReadContext {
 public:
  ReadContext(const XmlDocument& doc, model::ModelSpec& spec) : doc_(&doc), spec_(spec) {}

  const XmlDocument& doc() const { return *doc_; }
  /// Reads from `doc` from now on (a ForceSet file a tool adds to the model), with the frames
  /// and names of the model already read; `doc` must outlive its use.
  void SwitchDocument(const XmlDocument& doc) { doc_ = &doc; }
  model::ModelSpec& spec() { return spec_; }

  /// Adds a warning at `node`; the same (component kind, message) pair is kept once per file
  /// when `dedupe_key` is non-empty, so one odd property repeated 80 times is one line.
  void Warn(const pugi::xml_node& node, const std::string& component, const std::string& message,
            const std::string& dedupe_key = "");

  /// Registers a body frame (path "/ground" or "/bodyset/<name>").
  void AddBodyFrame(const std::string& path, int body, const pugi::xml_node& node);
  /// Registers an offset frame; it is resolved (and added to ModelSpec::frames) on demand.
  /// Returns false if `path` is already taken.
  bool AddOffsetFrame(const std::string& path, FrameEntry entry);
  /// Registers a 4.x Station (a point fixed to a frame) by its absolute path.
  void AddStation(const std::string& path, const pugi::xml_node& node) { stations_[path] = node; }
  /// True if a frame with this absolute path exists.
  bool HasFrame(const std::string& path) const { return frames_.count(path) != 0; }

  /// Resolves socket text `path` (absolute, or relative to `owner_path`) to a frame, resolving
  /// offsets down to a body. Fails at `socket` naming `component` when it does not exist.
  /// Returns the absolute path; `*entry` receives the resolved frame.
  std::string ResolveFrame(const std::string& owner_path, std::string_view path,
                           const pugi::xml_node& socket, const std::string& component,
                           const FrameEntry** entry);

  /// Resolves every registered offset frame (so unused ones are checked and listed too).
  void ResolveAllFrames();

  /// Joins `path` onto `owner_path` ("..", "." and empty segments handled); "" if it climbs
  /// above the root.
  static std::string JoinPath(const std::string& owner_path, std::string_view path);

  // Name indices kept in step with the spec, so every lookup is O(1) and a file with very many
  // elements cannot make reading quadratic (a hang, for practical purposes).
  /// The body with this name, or kNone.
  int BodyIndex(const std::string& name) const { return Lookup(body_names_, name); }
  void IndexBody(const std::string& name, int index) { body_names_.emplace(name, index); }
  /// The first joint with this name, or kNone.
  int JointIndex(const std::string& name) const { return Lookup(joint_names_, name); }
  /// True if a joint already has this path.
  bool JointPathTaken(const std::string& path) const { return joint_paths_.count(path) != 0; }
  void IndexJoint(const std::string& name, const std::string& path, int index) {
    joint_names_.emplace(name, index);
    joint_paths_.insert(path);
  }
  /// The coordinate with this path, or kNone.
  int CoordinateByPath(const std::string& path) const { return Lookup(coordinate_paths_, path); }
  /// The coordinates with this name, in file order (empty if none).
  const std::vector<int>& CoordinatesNamed(const std::string& name) const;
  void IndexCoordinate(const std::string& name, const std::string& path, int index) {
    coordinate_names_[name].push_back(index);
    coordinate_paths_.emplace(path, index);
  }
  /// True if a wrap object with this name exists on some body.
  bool HasWrapObject(const std::string& name) const { return wrap_names_.count(name) != 0; }
  void IndexWrapObject(const std::string& name) { wrap_names_.insert(name); }

 private:
  static int Lookup(const std::unordered_map<std::string, int>& map, const std::string& key) {
    auto it = map.find(key);
    return it == map.end() ? model::kNone : it->second;
  }
  FrameEntry& Resolve(const std::string& path, FrameEntry& entry);
  // A StationDefinedFrame's pose from its three stations and origin.
  void ResolveStationDefined(const std::string& path, FrameEntry& entry);
  // A station's body and location in it (p_BS), from its socket path relative to `owner`.
  std::pair<int, Vec3> ResolveStation(const std::string& owner, const pugi::xml_node& socket,
                                      const std::string& component);

  const XmlDocument* doc_;
  model::ModelSpec& spec_;
  std::unordered_map<std::string, FrameEntry> frames_;
  std::unordered_map<std::string, pugi::xml_node> stations_;
  std::vector<std::string> offset_order_;  // registration order, for stable frame listing
  std::set<std::string> warned_;
  std::unordered_multimap<std::string, std::string> frame_names_;  // last path segment -> path
  std::unordered_map<std::string, int> body_names_, joint_names_, coordinate_paths_;
  std::unordered_map<std::string, std::vector<int>> coordinate_names_;
  std::unordered_set<std::string> joint_paths_, wrap_names_;
  int resolve_depth_ = 0;  // offset frames being resolved, to bound the recursion
};

// ---- helpers shared by the reader's parts (osim_util.cc) ----

/// The first child element with this tag, or an empty node.
inline pugi::xml_node Child(const pugi::xml_node& node, const char* tag) { return node.child(tag); }
/// Lowercased copy.
std::string Lower(std::string_view s);
/// The `name` attribute ("" when absent).
inline std::string NameOf(const pugi::xml_node& node) { return node.attribute("name").value(); }
/// The element children of the list held by a set: `<XSet><objects>...</objects></XSet>`; also
/// accepts the list element itself (4.x `<frames>`, `<components>`, `<coordinates>`).
std::vector<pugi::xml_node> ObjectsOf(const pugi::xml_node& set_or_list);
/// Copies an element tree into a generic Element (tag, name, trimmed text, line, children).
model::Element ToElement(const XmlDocument& doc, const pugi::xml_node& node);
/// Reads the optional Vec3 child `tag` (default when absent or empty, as OpenSim does).
Vec3 ReadVec3Or(const XmlDocument& doc, const pugi::xml_node& parent, const char* tag,
                const std::string& component, const Vec3& fallback);
/// Reads the optional number child `tag`.
double ReadDoubleOr(const XmlDocument& doc, const pugi::xml_node& parent, const char* tag,
                    const std::string& component, double fallback);
/// Reads the optional boolean child `tag`.
bool ReadBoolOr(const XmlDocument& doc, const pugi::xml_node& parent, const char* tag,
                const std::string& component, bool fallback);
/// The trimmed text of child `tag` ("" when absent).
std::string TextOf(const pugi::xml_node& parent, const char* tag);

/// A component's on/off flag: `current_tag` (appliesForce, isEnforced) when present, else the
/// negation of the pre-30509 `isDisabled`, else `fallback`.
bool ReadEnabledFlag(const XmlDocument& doc, const pugi::xml_node& node, const char* current_tag,
                     const std::string& path, bool fallback);
/// X = [R(body-fixed XYZ angles), p].
Transform MakeTransform(const Vec3& angles, const Vec3& p);
/// True if the trimmed text is a non-empty whitespace-separated list of numbers.
bool IsNumberList(std::string_view text);
/// Numeric leaf children (not in `skip`) as a NumberMap.
model::NumberMap ReadNumericLeaves(const XmlDocument& doc, const pugi::xml_node& node,
                                   const std::string& component,
                                   std::initializer_list<std::string_view> skip);

/// The coordinate a property names (a 4.x path or a 3.x name); fails at `node` when there is
/// none; when several have that name, warns and takes the first (as OpenSim 3's lookup does).
int ResolveCoordinateName(ReadContext& ctx, const pugi::xml_node& node, std::string_view text,
                          const std::string& component);

// ---- the reader's parts ----

/// Ground and bodies (both layouts), their geometry and wrap objects, and every
/// PhysicalOffsetFrame of a 4.x document registered in the frame table.
void ReadBodies(ReadContext& ctx, const pugi::xml_node& model);
/// Geometry attached to a frame (4.x attached_geometry) or 3.x VisibleObject, added to `body`.
void ReadAttachedGeometry(ReadContext& ctx, const pugi::xml_node& owner,
                          const std::string& owner_path, const std::string& component);
void ReadVisibleObject(ReadContext& ctx, const pugi::xml_node& visible, int body,
                       const std::string& frame_path, const std::string& component);
/// Joints and their coordinates (4.x JointSet, 3.05 connectors, or 3.x joints nested in bodies).
void ReadJoints(ReadContext& ctx, const pugi::xml_node& model);
/// Forces (muscles included) and their geometry paths.
void ReadForces(ReadContext& ctx, const pugi::xml_node& model);
/// The forces of one <ForceSet> element (the model's, or a ForceSet file's) appended to the spec,
/// each marked with the format `version` of its document.
void ReadForceSet(ReadContext& ctx, const pugi::xml_node& force_set, int version);
/// The frames a force's sockets name and the function-valued properties its builder needs
/// (ForceSpec::frames, ForceSpec::functions).
void ReadForceAttachments(ReadContext& ctx, const pugi::xml_node& node, model::ForceSpec& force);
/// Constraints, markers, contact geometry, controllers, probes and other components.
void ReadOtherComponents(ReadContext& ctx, const pugi::xml_node& model);
/// Checks the assembled spec: duplicate names, bodies not connected to ground, cycles.
void ValidateSpec(ReadContext& ctx, const pugi::xml_node& model);

}  // namespace sinew::io::internal
