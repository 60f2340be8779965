// sinew.Error: the Python face of sinew::Error, an Exception whose message is the library's
// `file:line: component: message` and whose attributes hold the parts (file, line, component,
// message; file "" and line 0 when unknown).
#include <sinew/common/error.h>

#include "bindings.h"

namespace sinew::python {

void BindErrors(py::module_& m) {
  static py::handle error_type =
      PyErr_NewExceptionWithDoc("sinew.Error",
                                "Bad input or an impossible request. str(error) is "
                                "'file:line: component: message'; the attributes file, line, "
                                "component and message hold the parts.",
                                PyExc_Exception, nullptr);
  m.attr("Error") = error_type;
  py::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const Error& error) {
      py::object instance = error_type(error.what());
      instance.attr("file") = error.where().file;
      instance.attr("line") = error.where().line;
      instance.attr("component") = error.component();
      instance.attr("message") = error.message();
      PyErr_SetObject(error_type.ptr(), instance.ptr());
    }
  });
}

}  // namespace sinew::python
