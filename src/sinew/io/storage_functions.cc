#include <sinew/functions/gcv_spline.h>
#include <sinew/io/storage_functions.h>

#include <memory>

namespace sinew::io {

std::vector<functions::FunctionPtr> FitColumnSplines(const Storage& storage, int half_order) {
  std::vector<functions::FunctionPtr> functions;
  functions.reserve(storage.labels.size());
  for (int column = 0; column < storage.NumColumns(); ++column) {
    try {
      functions.push_back(
          std::make_shared<functions::GCVSpline>(half_order, storage.time, storage.Column(column)));
    } catch (const Error& error) {
      throw Error("column '" + storage.labels[column] + "': " + error.message());
    }
  }
  return functions;
}

}  // namespace sinew::io
