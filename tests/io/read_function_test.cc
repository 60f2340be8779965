#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/functions/constant.h>
#include <sinew/functions/gcv_spline.h>
#include <sinew/functions/linear_function.h>
#include <sinew/functions/multiplier_function.h>
#include <sinew/functions/piecewise_linear_function.h>
#include <sinew/functions/polynomial_function.h>
#include <sinew/functions/simm_spline.h>
#include <sinew/io/internal/read_function.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>

#include "corpus.h"

namespace sinew {
namespace {

// Parses `xml` and returns the function held by the root property element.
functions::FunctionPtr ReadRoot(const std::string& xml) {
  io::internal::XmlDocument doc = io::internal::XmlDocument::Parse(xml, "test.osim");
  return io::internal::ReadFunctionProperty(doc, doc.root(), "/jointset/knee_r");
}

TEST(ReadFunctionTest, InlineAndWrappedSimmSplineAreTheSame) {
  functions::FunctionPtr inline_form = ReadRoot(
      "<SimmSpline name=\"function\">\n"
      "  <!-- comment -->\n"
      "  <x>0 1 2 3 4</x>\n  <y> 0 1 4 9 17</y>\n</SimmSpline>");
  functions::FunctionPtr wrapped = ReadRoot(
      "<function>\n <SimmSpline>\n  <x>0 1 2 3 4</x>\n  <y>0 1 4 9 17</y>\n"
      " </SimmSpline>\n</function>");
  ASSERT_TRUE(inline_form && wrapped);
  EXPECT_EQ(inline_form->TypeName(), "SimmSpline");
  EXPECT_EQ(wrapped->TypeName(), "SimmSpline");
  for (double x : {-1.0, 0.3, 2.5, 3.9, 5.0}) {
    EXPECT_EQ(inline_form->Calc(x), wrapped->Calc(x));
  }
  // Knot values are reproduced.
  EXPECT_DOUBLE_EQ(wrapped->Calc(3.0), 9.0);
}

TEST(ReadFunctionTest, NaturalCubicSplineIsReadAsSimmSpline) {
  functions::FunctionPtr f = ReadRoot(
      "<NaturalCubicSpline name=\"\">\n<x> -1 0 1 2</x>\n<y> 1 0 1 4</y>\n</NaturalCubicSpline>");
  auto spline = std::dynamic_pointer_cast<const functions::SimmSpline>(f);
  ASSERT_TRUE(spline);
  // y = x^2 sampled at 4 knots: the FMM end conditions reproduce it exactly.
  EXPECT_NEAR(f->Calc(0.5), 0.25, 1e-14);
  EXPECT_EQ(ReadRoot("<natCubicSpline><x>0 1</x><y>0 1</y></natCubicSpline>")->TypeName(),
            "SimmSpline");
}

TEST(ReadFunctionTest, ConstantLinearPolynomial) {
  EXPECT_EQ(ReadRoot("<Constant name=\"function\"><value>       0.0027499999 </value></Constant>")
                ->Calc(7.0),
            0.0027499999);
  // A Constant without <value> is OpenSim's default 0.
  EXPECT_EQ(ReadRoot("<function><Constant/></function>")->Calc(1.0), 0.0);
  functions::FunctionPtr linear = ReadRoot(
      "<LinearFunction name=\"function\"><coefficients> -0.333333 1</coefficients>"
      "</LinearFunction>");
  EXPECT_DOUBLE_EQ(linear->Calc(3.0), -0.999999 + 1.0);
  EXPECT_DOUBLE_EQ(linear->CalcDerivative(3.0, 1), -0.333333);
  // Leading-dot numbers as in the corpus (".01 .2").
  EXPECT_DOUBLE_EQ(ReadRoot("<function><LinearFunction><coefficients> .01 .2</coefficients>"
                            "</LinearFunction></function>")
                       ->Calc(10.0),
                   0.3);
  // Decreasing powers: 2 x^2 - 3 x + 5.
  functions::FunctionPtr poly = ReadRoot(
      "<PolynomialFunction name=\"function\"><coefficients>2 -3 5</coefficients>"
      "</PolynomialFunction>");
  EXPECT_DOUBLE_EQ(poly->Calc(2.0), 7.0);
}

TEST(ReadFunctionTest, MultiplierFunctionWrapsTheInnerFunction) {
  functions::FunctionPtr f = ReadRoot(
      "<MultiplierFunction name=\"function\">\n"
      "  <function>\n    <SimmSpline>\n      <x> 0 3.14159</x>\n      <y> -0.122564 -0.123775</y>\n"
      "    </SimmSpline>\n  </function>\n  <scale>0.5</scale>\n</MultiplierFunction>");
  auto multiplier = std::dynamic_pointer_cast<const functions::MultiplierFunction>(f);
  ASSERT_TRUE(multiplier);
  EXPECT_EQ(multiplier->scale(), 0.5);
  EXPECT_EQ(multiplier->function()->TypeName(), "SimmSpline");
  EXPECT_DOUBLE_EQ(f->Calc(0.0), 0.5 * -0.122564);
  // Inner function written inline (4.x style) is accepted too.
  functions::FunctionPtr g = ReadRoot(
      "<MultiplierFunction name=\"function\"><LinearFunction name=\"function\">"
      "<coefficients>2 1</coefficients></LinearFunction><scale>3</scale></MultiplierFunction>");
  EXPECT_DOUBLE_EQ(g->Calc(1.0), 9.0);
}

TEST(ReadFunctionTest, PiecewiseLinearFunction) {
  functions::FunctionPtr f = ReadRoot(
      "<function><PiecewiseLinearFunction>\n<x> -1 0 2</x>\n<y> 0 1 0</y>\n"
      "</PiecewiseLinearFunction></function>");
  EXPECT_EQ(f->TypeName(), "PiecewiseLinearFunction");
  EXPECT_DOUBLE_EQ(f->Calc(1.0), 0.5);
}

TEST(ReadFunctionTest, OtherTypesWithTheirPropertyNames) {
  functions::FunctionPtr sine = ReadRoot(
      "<Sine name=\"f\"><amplitude>2</amplitude><omega>3</omega><phase>0.5</phase>"
      "<offset>1</offset></Sine>");
  EXPECT_DOUBLE_EQ(sine->Calc(0.2), 2.0 * std::sin(1.1) + 1.0);
  EXPECT_DOUBLE_EQ(ReadRoot("<Sine/>")->Calc(0.3), std::sin(0.3));  // OpenSim defaults
  functions::FunctionPtr step = ReadRoot(
      "<StepFunction><transition_start_time>1</transition_start_time>"
      "<transition_end_time>3</transition_end_time><start_value>2</start_value>"
      "<end_value>6</end_value></StepFunction>");
  EXPECT_DOUBLE_EQ(step->Calc(2.0), 4.0);
  functions::FunctionPtr default_step = ReadRoot("<StepFunction/>");  // 0.99 -> 1.01, 0 -> 1
  EXPECT_EQ(default_step->Calc(0.99), 0.0);
  EXPECT_DOUBLE_EQ(default_step->Calc(1.0), 0.5);
  EXPECT_EQ(default_step->Calc(1.01), 1.0);
  functions::FunctionPtr constant_steps =
      ReadRoot("<PiecewiseConstantFunction><x>0 1 2</x><y>5 6 7</y></PiecewiseConstantFunction>");
  EXPECT_EQ(constant_steps->Calc(1.5), 6.0);
  functions::FunctionPtr multivariate = ReadRoot(
      "<MultivariatePolynomialFunction>\n<coefficients>1 1 1 1</coefficients>\n"
      "<dimension>3</dimension>\n<order>1</order>\n</MultivariatePolynomialFunction>");
  EXPECT_EQ(multivariate->NumArguments(), 3);
  const double p[3] = {1.0, 2.0, 3.0};
  EXPECT_DOUBLE_EQ(multivariate->CalcN(p), 7.0);
  functions::FunctionPtr gcv = ReadRoot(
      "<GCVSpline name=\"spline_slider\"><half_order>3</half_order>"
      "<error_variance>0</error_variance><x> 0 0.1 0.2 0.3 0.4 0.5 0.6</x>"
      "<y> 0.5 0.4 0.3 0.18 0.09 0.04 -0.008</y><weights> 1 1 1 1 1 1 1</weights>"
      "<coefficients> 0 0 0 0 0 0 0</coefficients></GCVSpline>");
  EXPECT_NEAR(gcv->Calc(0.3), 0.18, 1e-14);
  // A smoothing fit (known error variance) is read too; it no longer interpolates.
  auto smoothed = std::dynamic_pointer_cast<const functions::GCVSpline>(ReadRoot(
      "<GCVSpline><half_order>2</half_order><error_variance>0.001</error_variance>"
      "<x> 0 0.1 0.2 0.3 0.4 0.5 0.6 0.7</x><y> 0.5 0.42 0.3 0.21 0.09 0.04 -0.01 -0.05</y>"
      "</GCVSpline>"));
  ASSERT_TRUE(smoothed);
  EXPECT_GT(smoothed->smoothing_parameter(), 0.0);
  for (const char* type :
       {"Constant", "SimmSpline", "NaturalCubicSpline", "GCVSpline", "Sine", "StepFunction",
        "MultivariatePolynomialFunction", "PiecewiseConstantFunction", "PiecewiseLinearFunction"}) {
    EXPECT_TRUE(io::internal::IsFunctionType(type)) << type;
  }
  EXPECT_FALSE(io::internal::IsFunctionType("function"));
  EXPECT_FALSE(io::internal::IsFunctionType("Body"));
}

TEST(ReadFunctionTest, FindsPropertiesInBothForms) {
  io::internal::XmlDocument doc = io::internal::XmlDocument::Parse(
      "<TransformAxis name=\"rotation1\">\n"
      "  <coordinates>knee_angle_r</coordinates>\n"
      "  <SimmSpline name=\"function\"><x>0 1</x><y>0 2</y></SimmSpline>\n"
      "</TransformAxis>\n",
      "a.osim");
  functions::FunctionPtr inline_form =
      io::internal::ReadFunctionProperty(doc, doc.root(), "function", "/a");
  ASSERT_TRUE(inline_form);
  EXPECT_DOUBLE_EQ(inline_form->Calc(0.5), 1.0);
  EXPECT_EQ(io::internal::ReadFunctionProperty(doc, doc.root(), "x_location", "/a"), nullptr);
  EXPECT_FALSE(
      io::internal::FindFunctionProperty(doc.root(), "coordinates").empty());  // a plain child too
  io::internal::XmlDocument wrapped = io::internal::XmlDocument::Parse(
      "<MovingPathPoint>\n  <x_location>\n    <NaturalCubicSpline name=\"\">\n"
      "      <x>0 1 2</x><y>0 1 4</y>\n    </NaturalCubicSpline>\n  </x_location>\n"
      "  <y_location/>\n</MovingPathPoint>\n",
      "b.osim");
  functions::FunctionPtr x =
      io::internal::ReadFunctionProperty(wrapped, wrapped.root(), "x_location", "/b");
  ASSERT_TRUE(x);
  EXPECT_DOUBLE_EQ(x->Calc(1.5), 2.25);  // three knots: the parabola
  EXPECT_EQ(io::internal::ReadFunctionProperty(wrapped, wrapped.root(), "y_location", "/b"),
            nullptr);
}

TEST(ReadFunctionTest, EmptyWrapperGivesNull) {
  EXPECT_EQ(ReadRoot("<function>\n  <!-- nothing -->\n</function>"), nullptr);
}

// Asserts that reading `xml` throws a sinew::Error at `line` mentioning `text`.
void ExpectError(const std::string& xml, int line, const std::string& text) {
  try {
    ReadRoot(xml);
    FAIL() << "no error for " << xml;
  } catch (const Error& error) {
    EXPECT_EQ(error.where().file, "test.osim");
    EXPECT_EQ(error.where().line, line) << error.what();
    EXPECT_EQ(error.component(), "/jointset/knee_r");
    EXPECT_NE(std::string(error.what()).find(text), std::string::npos) << error.what();
  }
}

TEST(ReadFunctionTest, ErrorsNameFileLineAndComponent) {
  ExpectError("<function>\n\n  <Spline3000><x>1 2</x></Spline3000>\n</function>", 3, "Spline3000");
  ExpectError("<SimmSpline>\n<x>0 1 2</x>\n<y>0 1</y>\n</SimmSpline>", 1, "x has 3 values");
  ExpectError("<SimmSpline>\n<x>0 1 2</x>\n</SimmSpline>", 1, "<y>");
  // Unsorted or repeated x: an error at <x>, naming the function.
  ExpectError("<SimmSpline>\n<x>0 2 1</x>\n<y>0 1 2</y></SimmSpline>", 2,
              "<SimmSpline>: x must be strictly increasing, but x[2] = 1 is below x[1] = 2");
  ExpectError("<SimmSpline name=\"f\">\n<x>0 1 1 2</x>\n<y>0 1 2 3</y></SimmSpline>", 2,
              "<SimmSpline name=\"f\">: x must be strictly increasing, but x[2] = 1 repeats x[1]");
  ExpectError("<PiecewiseLinearFunction>\n<x>0 0</x>\n<y>0 1</y></PiecewiseLinearFunction>", 2,
              "x[1] = 0 repeats x[0] = 0");
  ExpectError("<GCVSpline>\n<half_order>1</half_order><x>0 1 1</x>\n<y>0 1 2</y></GCVSpline>", 2,
              "<GCVSpline>: x must be strictly increasing");
  ExpectError("<SimmSpline>\n<x>0 1 2</x>\n<y>0 one 2</y></SimmSpline>", 3, "'one'");
  ExpectError("<SimmSpline>\n<x>0</x>\n<y>0</y></SimmSpline>", 1, "at least 2");
  ExpectError("<LinearFunction>\n<coefficients>1 2 3</coefficients></LinearFunction>", 2,
              "expects 2 numbers");
  ExpectError("<function>\n<Constant/>\n<Constant/>\n</function>", 3, "more than one");
  ExpectError("<MultiplierFunction>\n<scale>2</scale>\n</MultiplierFunction>", 1, "inner");
  ExpectError(
      "<StepFunction>\n<transition_start_time>1</transition_start_time>\n"
      "<transition_end_time>1</transition_end_time></StepFunction>",
      1, "must differ");
  ExpectError("<GCVSpline>\n<half_order>3</half_order><x>0 1 2 3</x><y>0 1 2 3</y></GCVSpline>", 1,
              "at least 6 points");
  ExpectError("<GCVSpline>\n<half_order>2.5</half_order></GCVSpline>", 2, "integer");
  ExpectError(
      "<MultivariatePolynomialFunction>\n<coefficients>1 1</coefficients>"
      "<dimension>3</dimension><order>1</order></MultivariatePolynomialFunction>",
      1, "need 4 coefficients");
}

// Reads every Function element in every model and setup file of the OpenSim corpus
// (SINEW_CORPUS_DIR). Every one must load, and a SimmSpline must reproduce its own knots.
TEST(ReadFunctionTest, ReadsEveryFunctionInTheCorpus) {
  SINEW_SKIP_WITHOUT_CORPUS();
  const std::filesystem::path root = testing::CorpusDir();
  std::map<std::string, int> counts;
  int files = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
    const std::string extension = entry.path().extension().string();
    if (!entry.is_regular_file() || (extension != ".osim" && extension != ".xml")) continue;
    std::optional<io::internal::XmlDocument> doc;
    try {
      doc.emplace(io::internal::XmlDocument::Load(entry.path().string()));
    } catch (const Error& error) {
      std::cout << "skipped: " << error.what() << "\n";
      continue;  // malformed XML is the osim reader's business, not this test's
    }
    ++files;
    for (const pugi::xpath_node& found : doc->root().select_nodes("//*")) {
      const pugi::xml_node node = found.node();
      if (!io::internal::IsFunctionType(node.name())) continue;
      functions::FunctionPtr f;
      EXPECT_NO_THROW(f = io::internal::ReadFunction(*doc, node, ""))
          << entry.path() << ":" << doc->LineOf(node);
      if (!f) continue;
      ++counts[node.name()];
      if (auto spline = std::dynamic_pointer_cast<const functions::SimmSpline>(f)) {
        for (size_t i = 0; i < spline->x().size(); ++i) {
          EXPECT_NEAR(spline->Calc(spline->x()[i]), spline->y()[i],
                      1e-12 * (1.0 + std::abs(spline->y()[i])))
              << entry.path() << ":" << doc->LineOf(node);
        }
      }
    }
  }
  for (const auto& [type, count] : counts) std::cout << type << ": " << count << "\n";
  // Counted in the corpus: 5,496 function elements. A change in any count means a file was
  // added to the corpus or the reader skips (or invents) functions; update on purpose only.
  const std::map<std::string, int> expected = {{"Constant", 1858},
                                               {"GCVSpline", 1},
                                               {"LinearFunction", 1128},
                                               {"MultiplierFunction", 570},
                                               {"MultivariatePolynomialFunction", 2},
                                               {"NaturalCubicSpline", 800},
                                               {"PiecewiseLinearFunction", 10},
                                               {"PolynomialFunction", 30},
                                               {"SimmSpline", 1097}};
  EXPECT_EQ(counts, expected);
  int total = 0;
  for (const auto& [type, count] : counts) total += count;
  EXPECT_EQ(total, 5496);
}

}  // namespace
}  // namespace sinew
