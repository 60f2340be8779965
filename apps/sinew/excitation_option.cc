#include "apps/sinew/excitation_option.h"

#include <sinew/common/error.h>
#include <sinew/common/text.h>
#include <sinew/functions/constant.h>
#include <sinew/functions/excitations.h>

#include <cmath>
#include <memory>
#include <vector>

namespace sinew::cli {
namespace {

// The comma-separated numbers of `args`, exactly `count` of them.
std::vector<double> Numbers(const std::string& option, const std::string& args, size_t count) {
  std::vector<double> values;
  size_t start = 0;
  while (start <= args.size()) {
    const size_t comma = args.find(',', start);
    const std::string token =
        args.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    double value = 0;
    if (!ParseNumber(TrimSpace(token), &value) || !std::isfinite(value)) {
      throw Error("--excitation " + option + ": '" + token + "' is not a finite number");
    }
    values.push_back(value);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (values.size() != count) {
    throw Error("--excitation " + option + ": expected " + std::to_string(count) +
                " comma-separated number(s)");
  }
  return values;
}

}  // namespace

std::pair<std::string, functions::FunctionPtr> ParseExcitationOption(const std::string& option) {
  const size_t equals = option.find('=');
  const size_t colon = option.find(':', equals == std::string::npos ? 0 : equals);
  if (equals == std::string::npos || equals == 0 || colon == std::string::npos) {
    throw Error("--excitation " + option +
                ": expected NAME=constant:V, NAME=ramp:START,SLOPE or "
                "NAME=sine:AMPLITUDE,FREQUENCY_HZ,PHASE");
  }
  const std::string name = option.substr(0, equals);
  const std::string kind = option.substr(equals + 1, colon - equals - 1);
  const std::string args = option.substr(colon + 1);
  if (kind == "constant") {
    return {name, std::make_shared<functions::Constant>(Numbers(option, args, 1)[0])};
  }
  if (kind == "ramp") {
    const std::vector<double> v = Numbers(option, args, 2);
    return {name, std::make_shared<functions::Ramp>(v[0], v[1])};
  }
  if (kind == "sine") {
    const std::vector<double> v = Numbers(option, args, 3);
    return {name, std::make_shared<functions::SineExcitation>(v[0], v[1], v[2])};
  }
  throw Error("--excitation " + option + ": unknown kind '" + kind + "' (constant, ramp or sine)");
}

}  // namespace sinew::cli
