// The exceptions, the thread setting and the report helpers shared by every bind_*.cpp.
#include <string>

#include "bindings.h"
#include "msmesh/errors.h"

namespace py = pybind11;

namespace msmesh::python {

namespace {

// The Python classes, created once in PYBIND11_MODULE and kept alive by the module.
struct ExceptionClasses {
  py::handle error, invalid_input, io_error, solver_error, cancelled;
};
ExceptionClasses& exception_classes() {
  static ExceptionClasses classes;
  return classes;
}

py::handle new_exception(py::module_& m, const char* name, const char* doc, const py::tuple& bases) {
  const std::string qualified = std::string("msmesh.") + name;
  PyObject* cls = PyErr_NewExceptionWithDoc(qualified.c_str(), doc, bases.ptr(), nullptr);
  if (!cls) throw py::error_already_set();
  m.attr(name) = py::reinterpret_borrow<py::object>(cls);  // the module holds one reference
  return cls;                                              // ... and the registry the other
}

}  // namespace

void register_exceptions(py::module_& m) {
  ExceptionClasses& c = exception_classes();
  c.error = new_exception(m, "Error", "Base class of every error msmesh raises.",
                          py::make_tuple(py::handle(PyExc_Exception)));
  c.invalid_input =
      new_exception(m, "InvalidInputError", "An input array, mesh or parameter is not acceptable (a ValueError).",
                    py::make_tuple(c.error, py::handle(PyExc_ValueError)));
  c.io_error = new_exception(m, "IoError", "Reading or writing a mesh file failed (an OSError).",
                             py::make_tuple(c.error, py::handle(PyExc_OSError)));
  c.solver_error = new_exception(m, "SolverError", "A linear solve or factorisation failed (a RuntimeError).",
                                 py::make_tuple(c.error, py::handle(PyExc_RuntimeError)));
  c.cancelled = new_exception(m, "Cancelled", "The progress callback returned False.", py::make_tuple(c.error));

  py::register_exception_translator([](std::exception_ptr p) {
    const ExceptionClasses& k = exception_classes();
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InvalidInput& e) {
      PyErr_SetString(k.invalid_input.ptr(), e.what());
    } catch (const IoError& e) {
      PyErr_SetString(k.io_error.ptr(), e.what());
    } catch (const SolverError& e) {
      PyErr_SetString(k.solver_error.ptr(), e.what());
    } catch (const Cancelled& e) {
      PyErr_SetString(k.cancelled.ptr(), e.what());
    } catch (const Error& e) {
      PyErr_SetString(k.error.ptr(), e.what());
    }
  });
}

// msmesh.set_threads(n): process-wide for Python (0: the default). The library's setting is
// OpenMP's, which belongs to each thread, so every call applies it in the thread it runs in.
std::atomic<int> g_threads{0};

py::dict normal_report(const NormalFilterStats& r) {
  py::dict d;
  d["normal_iterations"] = r.iterations;
  d["normal_converged"] = r.converged;
  d["residual_history"] = r.residual_history;
  d["normal_change_history"] = r.change_history;
  d["energy_history"] = r.energy_history;
  d["v_solver_iterations"] = r.v_solver_iterations;
  d["n_solver_iterations"] = r.n_solver_iterations;
  return d;
}

void add_vertex_report(py::dict& d, const VertexUpdateStats& r) {
  d["vertex_iterations"] = r.iterations;
  d["vertex_converged"] = r.converged;
  d["vertex_change_history"] = r.change_history;
  d["fallback_projections"] = static_cast<long long>(r.fallback_projections);
  d["vertex_solver_iterations"] = r.solver_iterations;
}

py::object bool_array(const std::vector<bool>& flags) {
  py::array_t<bool> a(static_cast<py::ssize_t>(flags.size()));
  auto m = a.mutable_unchecked<1>();
  for (size_t i = 0; i < flags.size(); ++i) m(static_cast<py::ssize_t>(i)) = flags[i];
  return std::move(a);
}

}  // namespace msmesh::python
