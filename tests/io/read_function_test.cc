#include "io/read_function.h"

#include <gtest/gtest.h>

#include "common/error.h"
#include "functions/constant.h"
#include "functions/linear_function.h"
#include "functions/multiplier_function.h"
#include "functions/piecewise_linear_function.h"
#include "functions/polynomial_function.h"
#include "functions/simm_spline.h"

namespace sinew {
namespace {

// Parses `xml` and returns the function held by the root property element.
FunctionPtr ReadRoot(const std::string& xml) {
  XmlDocument doc = XmlDocument::Parse(xml, "test.osim");
  return ReadFunctionProperty(doc, doc.root(), "/jointset/knee_r");
}

TEST(ReadFunctionTest, InlineAndWrappedSimmSplineAreTheSame) {
  FunctionPtr inline_form = ReadRoot(
      "<SimmSpline name=\"function\">\n"
      "  <!-- comment -->\n"
      "  <x>0 1 2 3 4</x>\n  <y> 0 1 4 9 17</y>\n</SimmSpline>");
  FunctionPtr wrapped = ReadRoot(
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
  FunctionPtr f = ReadRoot(
      "<NaturalCubicSpline name=\"\">\n<x> -1 0 1 2</x>\n<y> 1 0 1 4</y>\n</NaturalCubicSpline>");
  auto spline = std::dynamic_pointer_cast<const SimmSpline>(f);
  ASSERT_TRUE(spline);
  // y = x^2 sampled at 4 knots: the FMM end conditions reproduce it exactly.
  EXPECT_NEAR(f->Calc(0.5), 0.25, 1e-14);
}

TEST(ReadFunctionTest, ConstantLinearPolynomial) {
  EXPECT_EQ(ReadRoot("<Constant name=\"function\"><value>       0.0027499999 </value></Constant>")
                ->Calc(7.0),
            0.0027499999);
  // A Constant without <value> is OpenSim's default 0.
  EXPECT_EQ(ReadRoot("<function><Constant/></function>")->Calc(1.0), 0.0);
  FunctionPtr linear = ReadRoot(
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
  FunctionPtr poly = ReadRoot(
      "<PolynomialFunction name=\"function\"><coefficients>2 -3 5</coefficients>"
      "</PolynomialFunction>");
  EXPECT_DOUBLE_EQ(poly->Calc(2.0), 7.0);
}

TEST(ReadFunctionTest, MultiplierFunctionWrapsTheInnerFunction) {
  FunctionPtr f = ReadRoot(
      "<MultiplierFunction name=\"function\">\n"
      "  <function>\n    <SimmSpline>\n      <x> 0 3.14159</x>\n      <y> -0.122564 -0.123775</y>\n"
      "    </SimmSpline>\n  </function>\n  <scale>0.5</scale>\n</MultiplierFunction>");
  auto multiplier = std::dynamic_pointer_cast<const MultiplierFunction>(f);
  ASSERT_TRUE(multiplier);
  EXPECT_EQ(multiplier->scale(), 0.5);
  EXPECT_EQ(multiplier->function()->TypeName(), "SimmSpline");
  EXPECT_DOUBLE_EQ(f->Calc(0.0), 0.5 * -0.122564);
  // Inner function written inline (4.x style) is accepted too.
  FunctionPtr g = ReadRoot(
      "<MultiplierFunction name=\"function\"><LinearFunction name=\"function\">"
      "<coefficients>2 1</coefficients></LinearFunction><scale>3</scale></MultiplierFunction>");
  EXPECT_DOUBLE_EQ(g->Calc(1.0), 9.0);
}

TEST(ReadFunctionTest, PiecewiseLinearFunction) {
  FunctionPtr f = ReadRoot(
      "<function><PiecewiseLinearFunction>\n<x> -1 0 2</x>\n<y> 0 1 0</y>\n"
      "</PiecewiseLinearFunction></function>");
  EXPECT_EQ(f->TypeName(), "PiecewiseLinearFunction");
  EXPECT_DOUBLE_EQ(f->Calc(1.0), 0.5);
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
  ExpectError("<SimmSpline>\n<x>0 2 1</x>\n<y>0 1 2</y></SimmSpline>", 1, "non-decreasing");
  ExpectError("<SimmSpline>\n<x>0 1 2</x>\n<y>0 one 2</y></SimmSpline>", 3, "'one'");
  ExpectError("<SimmSpline>\n<x>0</x>\n<y>0</y></SimmSpline>", 1, "at least 2");
  ExpectError("<LinearFunction>\n<coefficients>1 2 3</coefficients></LinearFunction>", 2,
              "expects 2 numbers");
  ExpectError("<function>\n<Constant/>\n<Constant/>\n</function>", 3, "more than one");
  ExpectError("<MultiplierFunction>\n<scale>2</scale>\n</MultiplierFunction>", 1, "inner");
}

}  // namespace
}  // namespace sinew
