#include <sinew/functions/constant.h>
#include <sinew/functions/gcv_spline.h>
#include <sinew/functions/linear_function.h>
#include <sinew/functions/multiplier_function.h>
#include <sinew/functions/multivariate_polynomial_function.h>
#include <sinew/functions/piecewise_constant_function.h>
#include <sinew/functions/piecewise_linear_function.h>
#include <sinew/functions/polynomial_function.h>
#include <sinew/functions/simm_spline.h>
#include <sinew/functions/sine.h>
#include <sinew/functions/step_function.h>
#include <sinew/io/internal/read_function.h>

#include <array>
#include <cmath>
#include <sstream>
#include <string_view>

namespace sinew::io::internal {
namespace {

// Every Function class the reader knows, by its OpenSim tag.
constexpr std::array<std::string_view, 13> kFunctionTypes = {
    "Constant",
    "LinearFunction",
    "PolynomialFunction",
    "MultiplierFunction",
    "SimmSpline",
    "NaturalCubicSpline",  // OpenSim renames it SimmSpline
    "natCubicSpline",      // older name, also renamed SimmSpline
    "PiecewiseLinearFunction",
    "PiecewiseConstantFunction",
    "StepFunction",
    "Sine",
    "MultivariatePolynomialFunction",
    "GCVSpline",
};

// The single child element named `name`; a missing required one fails at `element`.
pugi::xml_node Child(const XmlDocument& doc, const pugi::xml_node& element, const char* name,
                     const std::string& component, bool required) {
  pugi::xml_node child = element.child(name);
  if (!child && required) {
    doc.Fail(element, component,
             "<" + std::string(element.name()) + "> needs a <" + name + "> property");
  }
  return child;
}

// An optional scalar property with OpenSim's default.
double ReadScalar(const XmlDocument& doc, const pugi::xml_node& element, const char* name,
                  const std::string& component, double default_value) {
  pugi::xml_node child = element.child(name);
  return child ? doc.ReadDouble(child, component) : default_value;
}

// A required integer property.
int ReadInteger(const XmlDocument& doc, const pugi::xml_node& element, const char* name,
                const std::string& component) {
  pugi::xml_node child = Child(doc, element, name, component, true);
  const double value = doc.ReadDouble(child, component);
  if (!(std::abs(value) < 1e6) || value != std::round(value)) {
    doc.Fail(child, component, "<" + std::string(name) + "> expects an integer");
  }
  return static_cast<int>(value);
}

std::vector<double> ReadList(const XmlDocument& doc, const pugi::xml_node& element,
                             const char* name, const std::string& component) {
  return doc.ReadNumbers(Child(doc, element, name, component, true), component);
}

// Builds the function, turning a sinew::Error from a constructor (bad knots, ...) into one that
// names the element's file and line.
template <typename Make>
functions::FunctionPtr Build(const XmlDocument& doc, const pugi::xml_node& element,
                             const std::string& component, Make make) {
  try {
    return make();
  } catch (const Error& error) {
    if (!error.where().file.empty()) throw;
    doc.Fail(element, component, error.message());
  }
}

// How messages name a function: "<SimmSpline name=\"knee_tx\">", or the tag alone.
std::string FunctionName(const pugi::xml_node& element) {
  const std::string name = element.attribute("name").value();
  return "<" + std::string(element.name()) + (name.empty() ? "" : " name=\"" + name + "\"") + ">";
}

// A spline or piecewise linear function needs x strictly increasing: unsorted x has no meaning,
// and a repeated x makes a slope of (y step) / 1e-7 (OpenSim's smallest spacing), which stalls
// an integrator far from here. A step function (PiecewiseConstantFunction) may repeat an x.
void CheckIncreasing(const XmlDocument& doc, const pugi::xml_node& element,
                     const std::string& component, const std::vector<double>& x) {
  for (size_t i = 1; i < x.size(); ++i) {
    if (x[i] > x[i - 1]) continue;
    std::ostringstream text;
    text << FunctionName(element) << ": x must be strictly increasing, but x[" << i
         << "] = " << x[i] << (x[i] == x[i - 1] ? " repeats" : " is below") << " x[" << i - 1
         << "] = " << x[i - 1];
    doc.Fail(element.child("x"), component, text.str());
  }
}

functions::FunctionPtr ReadKnotFunction(const XmlDocument& doc, const pugi::xml_node& element,
                                        const std::string& component, std::string_view type) {
  std::vector<double> x = ReadList(doc, element, "x", component);
  std::vector<double> y = ReadList(doc, element, "y", component);
  if (type != "PiecewiseConstantFunction") CheckIncreasing(doc, element, component, x);
  return Build(doc, element, component, [&]() -> functions::FunctionPtr {
    if (type == "PiecewiseLinearFunction") {
      return std::make_shared<functions::PiecewiseLinearFunction>(std::move(x), std::move(y));
    }
    if (type == "PiecewiseConstantFunction") {
      return std::make_shared<functions::PiecewiseConstantFunction>(std::move(x), std::move(y));
    }
    return std::make_shared<functions::SimmSpline>(std::move(x), std::move(y));
  });
}

}  // namespace

bool IsFunctionType(const std::string& tag) {
  for (std::string_view type : kFunctionTypes) {
    if (type == tag) return true;
  }
  return false;
}

functions::FunctionPtr ReadFunction(const XmlDocument& doc, const pugi::xml_node& element,
                                    const std::string& component) {
  const std::string type = element.name();
  if (type == "Constant") {
    return std::make_shared<functions::Constant>(ReadScalar(doc, element, "value", component, 0.0));
  }
  if (type == "LinearFunction") {
    pugi::xml_node coefficients = Child(doc, element, "coefficients", component, false);
    if (!coefficients) return std::make_shared<functions::LinearFunction>(1.0, 0.0);
    std::vector<double> c = doc.ReadNumbers(coefficients, component, 2);
    return std::make_shared<functions::LinearFunction>(c[0], c[1]);
  }
  if (type == "PolynomialFunction") {
    std::vector<double> c = ReadList(doc, element, "coefficients", component);
    return std::make_shared<functions::PolynomialFunction>(std::move(c));
  }
  if (type == "MultiplierFunction") {
    const double scale = ReadScalar(doc, element, "scale", component, 1.0);
    // The inner function: wrapped (<function><SimmSpline>...) or, as 4.x may write it, a
    // Function element of its own named "function".
    functions::FunctionPtr inner;
    if (pugi::xml_node wrapper = element.child("function")) {
      inner = ReadFunctionProperty(doc, wrapper, component);
    } else {
      for (pugi::xml_node child : element.children()) {
        if (child.type() == pugi::node_element && IsFunctionType(child.name())) {
          inner = ReadFunction(doc, child, component);
          break;
        }
      }
    }
    if (!inner) doc.Fail(element, component, "<MultiplierFunction> has no inner <function>");
    return std::make_shared<functions::MultiplierFunction>(std::move(inner), scale);
  }
  if (type == "SimmSpline" || type == "NaturalCubicSpline" || type == "natCubicSpline" ||
      type == "PiecewiseLinearFunction" || type == "PiecewiseConstantFunction") {
    return ReadKnotFunction(doc, element, component, type);
  }
  if (type == "Sine") {
    return std::make_shared<functions::Sine>(ReadScalar(doc, element, "amplitude", component, 1.0),
                                             ReadScalar(doc, element, "omega", component, 1.0),
                                             ReadScalar(doc, element, "phase", component, 0.0),
                                             ReadScalar(doc, element, "offset", component, 0.0));
  }
  if (type == "StepFunction") {
    const double x0 = ReadScalar(doc, element, "transition_start_time", component, 0.99);
    const double x1 = ReadScalar(doc, element, "transition_end_time", component, 1.01);
    const double y0 = ReadScalar(doc, element, "start_value", component, 0.0);
    const double y1 = ReadScalar(doc, element, "end_value", component, 1.0);
    return Build(doc, element, component, [&]() -> functions::FunctionPtr {
      return std::make_shared<functions::StepFunction>(x0, x1, y0, y1);
    });
  }
  if (type == "GCVSpline") {
    // OpenSim refits from x, y and error_variance; stored weights/coefficients are not used.
    const int half_order = ReadInteger(doc, element, "half_order", component);
    const double error_variance = ReadScalar(doc, element, "error_variance", component, 0.0);
    std::vector<double> x = ReadList(doc, element, "x", component);
    std::vector<double> y = ReadList(doc, element, "y", component);
    CheckIncreasing(doc, element, component, x);
    return Build(doc, element, component, [&]() -> functions::FunctionPtr {
      return std::make_shared<functions::GCVSpline>(half_order, std::move(x), std::move(y),
                                                    error_variance);
    });
  }
  if (type == "MultivariatePolynomialFunction") {
    std::vector<double> c = ReadList(doc, element, "coefficients", component);
    const int dimension = ReadInteger(doc, element, "dimension", component);
    const int order = ReadInteger(doc, element, "order", component);
    return Build(doc, element, component, [&]() -> functions::FunctionPtr {
      return std::make_shared<functions::MultivariatePolynomialFunction>(std::move(c), dimension,
                                                                         order);
    });
  }
  doc.Fail(element, component, "unknown or unsupported function type <" + type + ">");
}

functions::FunctionPtr ReadFunctionProperty(const XmlDocument& doc, const pugi::xml_node& property,
                                            const std::string& component) {
  if (IsFunctionType(property.name())) return ReadFunction(doc, property, component);
  // A wrapper: at most one Function element inside.
  pugi::xml_node function;
  for (pugi::xml_node child : property.children()) {
    if (child.type() != pugi::node_element) continue;
    if (function) {
      doc.Fail(child, component,
               "<" + std::string(property.name()) + "> holds more than one function");
    }
    function = child;
  }
  if (!function) return nullptr;
  return ReadFunction(doc, function, component);
}

pugi::xml_node FindFunctionProperty(const pugi::xml_node& parent, const std::string& property) {
  for (pugi::xml_node child : parent.children()) {
    if (child.type() != pugi::node_element) continue;
    if (property == child.name()) return child;
    if (IsFunctionType(child.name()) && property == child.attribute("name").value()) return child;
  }
  return {};
}

functions::FunctionPtr ReadFunctionProperty(const XmlDocument& doc, const pugi::xml_node& parent,
                                            const std::string& property,
                                            const std::string& component) {
  pugi::xml_node node = FindFunctionProperty(parent, property);
  return node ? ReadFunctionProperty(doc, node, component) : nullptr;
}

}  // namespace sinew::io::internal
