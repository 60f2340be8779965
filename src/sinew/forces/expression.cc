#include <muParser.h>
#include <sinew/common/error.h>
#include <sinew/forces/expression.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <mutex>

namespace sinew::forces {
namespace {

// Lepton's functions that muparser does not define (OpenSim's expressions may use them).
double Step(double x) { return x >= 0.0 ? 1.0 : 0.0; }
double Delta(double x) { return x == 0.0 ? 1.0 : 0.0; }
double Square(double x) { return x * x; }
double Cube(double x) { return x * x * x; }
double Recip(double x) { return 1.0 / x; }
double Erf(double x) { return std::erf(x); }
double Erfc(double x) { return std::erfc(x); }
double Floor(double x) { return std::floor(x); }
double Ceil(double x) { return std::ceil(x); }
double Atan2(double y, double x) { return std::atan2(y, x); }
double Select(double x, double y, double z) { return x != 0.0 ? y : z; }

}  // namespace

struct Expression::Parsed {
  std::string text;
  std::vector<std::string> names;
  mutable std::vector<double> values;  // muparser reads the variables from here
  mutable mu::Parser parser;
  mutable std::mutex mutex;  // muparser's evaluation writes to its own stack
};

Expression::Expression(const std::string& text, std::vector<std::string> variables)
    : parsed_(std::make_unique<Parsed>()) {
  Parsed& p = *parsed_;
  p.text = text;
  p.text.erase(std::remove_if(p.text.begin(), p.text.end(),
                              [](unsigned char c) { return std::isspace(c) != 0; }),
               p.text.end());
  p.names = std::move(variables);
  p.values.assign(p.names.size(), 0.0);
  try {
    for (size_t i = 0; i < p.names.size(); ++i) p.parser.DefineVar(p.names[i], &p.values[i]);
    p.parser.DefineFun("step", Step);
    p.parser.DefineFun("delta", Delta);
    p.parser.DefineFun("square", Square);
    p.parser.DefineFun("cube", Cube);
    p.parser.DefineFun("recip", Recip);
    p.parser.DefineFun("erf", Erf);
    p.parser.DefineFun("erfc", Erfc);
    p.parser.DefineFun("floor", Floor);
    p.parser.DefineFun("ceil", Ceil);
    p.parser.DefineFun("atan2", Atan2);
    p.parser.DefineFun("select", Select);
    p.parser.SetExpr(p.text);
    p.parser.Eval();  // parses now, so a malformed formula fails here and not mid-simulation
  } catch (const mu::Parser::exception_type& error) {
    std::string names;
    for (const std::string& name : p.names) names += (names.empty() ? "" : ", ") + name;
    throw Error("expression '" + p.text + "': " + error.GetMsg() + " (variables: " + names + ")");
  }
}

Expression::~Expression() = default;

const std::string& Expression::text() const { return parsed_->text; }

double Expression::Evaluate(std::span<const double> values) const {
  const Parsed& p = *parsed_;
  std::lock_guard<std::mutex> lock(p.mutex);
  std::copy(values.begin(), values.end(), p.values.begin());
  return p.parser.Eval();
}

}  // namespace sinew::forces
