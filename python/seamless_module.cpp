// SPDX-License-Identifier: MIT
// The extension module seamless._seamless, re-exported by the package
// seamless (python/seamless/__init__.py); docs/python.md documents the API.
#include "bindings.h"

#include <pybind11/stl.h>

#include <atomic>
#include <exception>
#include <filesystem>
#include <mutex>

namespace seamless::python {

py::object from_json(const std::string& text) {
    return py::module_::import("json").attr("loads")(py::str(text));
}

bool is_path(py::handle h) {
    return py::isinstance<py::str>(h) || py::hasattr(h, "__fspath__");
}

std::string path_string(py::handle h) {
    return py::str(py::module_::import("os").attr("fspath")(h)).cast<std::string>();
}

struct ProgressCallback::State {
    py::object callable; // destroyed with the GIL held: the caller's thread owns State
    std::atomic<bool> failed{false};
    std::mutex lock;
    std::exception_ptr error;
};

ProgressCallback::ProgressCallback(py::object callable) : state_(std::make_shared<State>()) {
    state_->callable = std::move(callable);
}

std::function<void(double)> ProgressCallback::function() {
    if (state_->callable.is_none()) return {};
    State* s = state_.get();
    return [s](double fraction) {
        if (s->failed.load()) return;
        py::gil_scoped_acquire gil;
        try {
            s->callable(fraction);
        } catch (...) { // kept for rethrow(): a worker thread cannot raise into Python
            const std::lock_guard<std::mutex> hold(s->lock);
            if (!s->failed.exchange(true)) s->error = std::current_exception();
        }
    };
}

void ProgressCallback::rethrow() {
    if (state_->error) std::rethrow_exception(std::exchange(state_->error, nullptr));
}

} // namespace seamless::python

PYBIND11_MODULE(_seamless, m) {
    using namespace seamless::python;
    m.doc() = "seamless: crack-free tessellation, watertightness checks and interval ray "
              "tracing of B-spline surfaces (docs/python.md)";
    bind_errors(m);
    bind_model(m);
    bind_mesh(m);
    bind_tessellate(m);
    bind_check(m);
    bind_render(m);
}
