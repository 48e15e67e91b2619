// SPDX-License-Identifier: MIT
// seamless.InputError: the library's InputError (bad input, the one line
// the CLI prints after "error: ") as a ValueError, with its file, field and
// message as attributes.
#include "bindings.h"

#include <seamless/base/error.h>

namespace seamless::python {

void bind_errors(py::module_& m) {
    // Leaked on purpose: the exception type lives as long as the interpreter.
    static auto* type = new py::exception<InputError>(m, "InputError", PyExc_ValueError);
    type->attr("__module__") = "seamless";
    type->doc() = "Bad input: the file and field at fault and what is wrong, in one line "
                  "(the message `seamless` prints after 'error: ').";
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const InputError& e) {
            py::object error = py::reinterpret_borrow<py::object>(type->ptr())(e.what());
            error.attr("file") = e.file();
            error.attr("field") = e.field();
            error.attr("message") = e.message();
            PyErr_SetObject(type->ptr(), error.ptr());
        }
    });
}

} // namespace seamless::python
