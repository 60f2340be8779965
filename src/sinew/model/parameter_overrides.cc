#include <sinew/common/error.h>
#include <sinew/common/text.h>
#include <sinew/model/parameter_overrides.h>

#include <charconv>
#include <functional>
#include <string_view>

namespace sinew::model {
namespace {

// Throws the error of override `key`, naming the model file, `line` and `component`.
[[noreturn]] void FailOverride(const ModelSpec& spec, int line, const std::string& component,
                               const std::string& key, const std::string& message) {
  throw Error(SourceLocation{spec.file, line}, component, "parameter '" + key + "': " + message);
}

// Where an override applies and how to report it: the model file and the component.
struct Target {
  const ModelSpec& spec;
  std::string key;        // as given: "BIClong/max_isometric_force"
  std::string property;   // "max_isometric_force"
  std::string component;  // the component's path, for errors
  int line = 0;           // the component's line

  [[noreturn]] void Fail(const std::string& message, int at_line = 0) const {
    FailOverride(spec, at_line > 0 ? at_line : line, component, key, message);
  }
};

// "a, b, c" of at most 10 names ("..." after).
std::string JoinNames(const std::vector<std::string>& names) {
  constexpr size_t kMaxShown = 10;
  std::string list;
  for (size_t i = 0; i < names.size() && i < kMaxShown; ++i) {
    list += (i == 0 ? "" : ", ") + names[i];
  }
  if (names.size() > kMaxShown) list += ", ...";
  return list.empty() ? "none" : list;
}

// Checks the count and the numbers of `values` for a property of `count` numbers.
void CheckValues(const Target& target, const std::vector<double>& values, size_t count,
                 NumberRange range, int line = 0) {
  if (values.size() != count) {
    target.Fail("expects " + std::to_string(count) + " number" + (count == 1 ? "" : "s") +
                    ", given " + std::to_string(values.size()),
                line);
  }
  if (FindOutOfRange(values, range) != nullptr) {
    target.Fail(range == NumberRange::kFinite ? "expects finite numbers (no NaN or infinity)"
                                              : "expects numbers (no NaN)",
                line);
  }
}

// A property of a typed spec (BodySpec, CoordinateSpec): how many numbers it takes, which, and
// how it stores them (returning "" or why the values cannot be taken).
template <typename Spec>
struct TypedProperty {
  std::string_view name;
  size_t count;
  NumberRange range;
  std::string (*set)(Spec&, const std::vector<double>&);
};

// One entry of the symmetric inertia (the 3.x properties inertia_xx ... inertia_yz).
template <int kRow, int kCol>
std::string SetInertiaEntry(BodySpec& body, const std::vector<double>& v) {
  if (kRow == kCol && v[0] < 0) return "a moment of inertia cannot be negative";
  body.inertia(kRow, kCol) = v[0];
  body.inertia(kCol, kRow) = v[0];
  return "";
}

const std::vector<TypedProperty<BodySpec>>& BodyProperties() {
  static const std::vector<TypedProperty<BodySpec>> properties = {
      {"mass", 1, NumberRange::kFinite,
       [](BodySpec& b, const std::vector<double>& v) -> std::string {
         if (v[0] < 0) return "a mass cannot be negative";
         b.mass = v[0];
         return "";
       }},
      {"mass_center", 3, NumberRange::kFinite,
       [](BodySpec& b, const std::vector<double>& v) -> std::string {
         b.mass_center = Vec3(v[0], v[1], v[2]);
         return "";
       }},
      // [Ixx Iyy Izz Ixy Ixz Iyz], as the 4.x <inertia> property.
      {"inertia", 6, NumberRange::kFinite,
       [](BodySpec& b, const std::vector<double>& v) -> std::string {
         if (v[0] < 0 || v[1] < 0 || v[2] < 0) return "a moment of inertia cannot be negative";
         b.inertia << v[0], v[3], v[4], v[3], v[1], v[5], v[4], v[5], v[2];
         return "";
       }},
      {"inertia_xx", 1, NumberRange::kFinite, SetInertiaEntry<0, 0>},
      {"inertia_yy", 1, NumberRange::kFinite, SetInertiaEntry<1, 1>},
      {"inertia_zz", 1, NumberRange::kFinite, SetInertiaEntry<2, 2>},
      {"inertia_xy", 1, NumberRange::kFinite, SetInertiaEntry<0, 1>},
      {"inertia_xz", 1, NumberRange::kFinite, SetInertiaEntry<0, 2>},
      {"inertia_yz", 1, NumberRange::kFinite, SetInertiaEntry<1, 2>},
  };
  return properties;
}

const std::vector<TypedProperty<CoordinateSpec>>& CoordinateProperties() {
  static const std::vector<TypedProperty<CoordinateSpec>> properties = {
      {"default_value", 1, NumberRange::kFinite,
       [](CoordinateSpec& c, const std::vector<double>& v) -> std::string {
         c.default_value = v[0];
         return "";
       }},
      {"default_speed_value", 1, NumberRange::kFinite,
       [](CoordinateSpec& c, const std::vector<double>& v) -> std::string {
         c.default_speed_value = v[0];
         return "";
       }},
      {"range", 2, NumberRange::kAllowInfinite,
       [](CoordinateSpec& c, const std::vector<double>& v) -> std::string {
         if (v[0] > v[1]) return "the range's minimum exceeds its maximum";
         c.range_min = v[0];
         c.range_max = v[1];
         return "";
       }},
  };
  return properties;
}

template <typename Spec>
void SetTyped(const Target& target, const std::vector<TypedProperty<Spec>>& properties, Spec& spec,
              const std::vector<double>& values) {
  std::vector<std::string> names;
  for (const TypedProperty<Spec>& property : properties) {
    names.emplace_back(property.name);
    if (property.name != target.property) continue;
    CheckValues(target, values, property.count, property.range);
    if (const std::string why = property.set(spec, values); !why.empty()) target.Fail(why);
    return;
  }
  target.Fail("no such property; the properties that can be overridden: " + JoinNames(names));
}

// Properties of a force's element that the reader has already turned into typed data (the 3.x
// offsets of a force's frames): changing the element would change nothing.
bool IsResolvedByReader(std::string_view property) {
  static constexpr std::string_view kResolved[] = {"location_body_1", "orientation_body_1",
                                                   "location_body_2", "orientation_body_2"};
  for (std::string_view resolved : kResolved) {
    if (property == resolved) return true;
  }
  return false;
}

// The shortest text that reads back as exactly `values`.
std::string FormatNumbers(const std::vector<double>& values) {
  std::string text;
  for (double value : values) {
    char buffer[64];
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof(buffer), value);
    if (!text.empty()) text += ' ';
    text.append(buffer, ec == std::errc() ? end : buffer);
  }
  return text;
}

// A numeric property written in the element (as its builder reads it, through ElementValues):
// its text is replaced by the new numbers, as many as the file writes. Infinity is passed on
// for the builder to accept (a bound such as max_control) or reject, naming the property.
void SetElementProperty(const Target& target, Element& element, const std::vector<double>& values) {
  std::vector<std::string> numeric;
  Element* found = nullptr;
  for (Element& child : element.children) {
    std::vector<double> numbers;
    const bool is_numeric = child.children.empty() && !child.text.empty() &&
                            ParseNumbers(child.text, &numbers) && !IsResolvedByReader(child.tag);
    if (is_numeric) numeric.push_back(child.tag);
    if (child.tag == target.property && !found) found = &child;
  }
  const std::string numeric_list = "; its numeric properties: " + JoinNames(numeric);
  if (!found) target.Fail("the file gives no such property" + numeric_list);
  if (IsResolvedByReader(found->tag)) {
    target.Fail("a frame offset, resolved when the file is read: cannot be overridden yet",
                found->line);
  }
  std::vector<double> written;
  if (!found->children.empty() || !ParseNumbers(found->text, &written) || written.empty()) {
    target.Fail("not a numeric property (the file writes '" +
                    (found->children.empty() ? found->text : "<" + found->tag + ">...") + "')" +
                    numeric_list,
                found->line);
  }
  CheckValues(target, values, written.size(), NumberRange::kAllowInfinite, found->line);
  found->text = FormatNumbers(values);
}

// A component an override may name.
struct Candidate {
  std::string_view kind;  // "body", "joint", ...
  const std::string* name;
  const std::string* path;
  int line;
  // Applies an override to it; null for kinds that cannot be overridden yet.
  std::function<void(const Target&, const std::vector<double>&)> apply;
};

template <typename T>
void AddCandidates(std::vector<Candidate>& out, std::string_view kind, std::vector<T>& items,
                   std::function<void(T&, const Target&, const std::vector<double>&)> apply) {
  for (T& item : items) {
    const std::string* path = &item.name;
    if constexpr (requires { item.path; }) path = &item.path;
    Candidate candidate{kind, &item.name, path, item.where.line, nullptr};
    if (apply) {
      candidate.apply = [&item, apply](const Target& target, const std::vector<double>& values) {
        apply(item, target, values);
      };
    }
    out.push_back(std::move(candidate));
  }
}

// Every named component of the spec, those that can be overridden first (ground excluded: it
// has no mass properties).
std::vector<Candidate> ListCandidates(ModelSpec& spec) {
  std::vector<Candidate> out;
  AddCandidates<BodySpec>(out, "body", spec.bodies,
                          [](BodySpec& body, const Target& target, const std::vector<double>& v) {
                            if (body.path == "/ground")
                              target.Fail("ground has no mass properties");
                            SetTyped(target, BodyProperties(), body, v);
                          });
  AddCandidates<CoordinateSpec>(
      out, "coordinate", spec.coordinates,
      [](CoordinateSpec& c, const Target& target, const std::vector<double>& v) {
        SetTyped(target, CoordinateProperties(), c, v);
      });
  AddCandidates<ForceSpec>(out, "force", spec.forces,
                           [](ForceSpec& f, const Target& target, const std::vector<double>& v) {
                             SetElementProperty(target, f.element, v);
                           });
  AddCandidates<JointSpec>(out, "joint", spec.joints, nullptr);
  AddCandidates<FrameSpec>(out, "frame", spec.frames, nullptr);
  AddCandidates<ConstraintSpec>(out, "constraint", spec.constraints, nullptr);
  AddCandidates<MarkerSpec>(out, "marker", spec.markers, nullptr);
  AddCandidates<ControllerSpec>(out, "controller", spec.controllers, nullptr);
  AddCandidates<ContactGeometrySpec>(out, "contact geometry", spec.contact_geometry, nullptr);
  return out;
}

// The one component `name` (a name, or a path when it starts with '/') designates among those
// that can be overridden; fails naming the close names, the paths of an ambiguous name, or the
// kind of a component that cannot be overridden yet.
const Candidate& Resolve(const ModelSpec& spec, const std::vector<Candidate>& candidates,
                         const std::string& key, const std::string& name) {
  const bool by_path = !name.empty() && name.front() == '/';
  std::vector<const Candidate*> matches, fixed;
  std::vector<std::string> names;
  for (const Candidate& c : candidates) {
    if (c.apply) names.push_back(by_path ? *c.path : *c.name);
    if ((by_path ? *c.path : *c.name) != name) continue;
    (c.apply ? matches : fixed).push_back(&c);
  }
  if (matches.size() == 1) return *matches.front();
  if (matches.size() > 1) {
    std::vector<std::string> paths;
    for (const Candidate* c : matches)
      paths.push_back(*c->path + " (" + std::string(c->kind) + ")");
    FailOverride(spec, 0, name, key,
                 "ambiguous: " + std::to_string(matches.size()) +
                     " components have this name; name one by its path: " + JoinNames(paths));
  }
  if (!fixed.empty()) {
    const Candidate& c = *fixed.front();
    FailOverride(spec, c.line, *c.path, key,
                 "a " + std::string(c.kind) +
                     "'s properties cannot be overridden yet (only bodies' mass properties, "
                     "coordinates' defaults and range, and forces' numeric properties)");
  }
  const std::vector<std::string> close = FindCloseNames(name, names);
  FailOverride(spec, 0, name, key,
               "no body, coordinate or force has this " + std::string(by_path ? "path" : "name") +
                   (close.empty() ? "" : " (close names: " + JoinNames(close) + ")"));
}

}  // namespace

void ApplyParameterOverrides(ModelSpec& spec, const std::vector<ParameterOverride>& overrides) {
  if (overrides.empty()) return;
  const std::vector<Candidate> candidates = ListCandidates(spec);
  for (const ParameterOverride& override : overrides) {
    const size_t slash = override.key.rfind('/');
    if (slash == std::string::npos || slash == 0 || slash + 1 == override.key.size()) {
      throw Error(SourceLocation{spec.file, 0}, override.key,
                  "a parameter is named '<component>/<property>' (e.g. "
                  "'BIClong/max_isometric_force' or '/bodyset/r_humerus/mass')");
    }
    const std::string name = override.key.substr(0, slash);
    const Candidate& candidate = Resolve(spec, candidates, override.key, name);
    const Target target{spec, override.key, override.key.substr(slash + 1), *candidate.path,
                        candidate.line};
    candidate.apply(target, override.values);
  }
}

}  // namespace sinew::model
