// Shared pieces of the msmesh._core bindings (python/src/bind_*.cpp, one file per area).
//
// This layer only converts: numpy arrays to Eigen (copies, made while the GIL is held), calls
// the library with the GIL released, and turns results into dicts of numpy arrays. Argument
// checking that gives friendly messages (shapes, dtypes, index ranges) lives in
// msmesh/__init__.py; the library validates again and throws msmesh::InvalidInput, which
// arrives in Python as msmesh.InvalidInputError (a ValueError).
#pragma once
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <Eigen/Core>
#include <atomic>
#include <chrono>
#include <exception>
#include <string>
#include <utility>
#include <vector>

#include "msmesh/denoise.h"
#include "msmesh/normal_filter.h"
#include "msmesh/progress.h"
#include "msmesh/threads.h"
#include "msmesh/vertex_update.h"

namespace py = pybind11;

namespace msmesh::python {

// Results go back as C-contiguous (row-major) arrays, the layout numpy users expect.
using RowMatrixXd = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using RowMatrixXi = Eigen::Matrix<int, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

inline py::object to_numpy(const Eigen::MatrixXd& M) { return py::cast(RowMatrixXd(M)); }
inline py::object to_numpy(const Eigen::MatrixXi& M) { return py::cast(RowMatrixXi(M)); }
inline py::object to_numpy(const Eigen::VectorXd& x) { return py::cast(Eigen::VectorXd(x)); }
py::object bool_array(const std::vector<bool>& flags);

/// The msmesh exception classes and the translator from the library's typed errors.
void register_exceptions(py::module_& m);

// Bridges a Python progress callable (or None) to a ProgressCallback. The callback runs on a
// thread that does not hold the GIL, so it takes the GIL for the duration of the Python call
// only. A Python exception raised by the callable (or a pending KeyboardInterrupt) is kept and
// cancels the computation; run_without_gil() re-raises it once the GIL is back.
class ProgressBridge {
 public:
  explicit ProgressBridge(py::object callable) : callable_(std::move(callable)) {}

  ProgressCallback callback() {
    return [this](const ProgressEvent& event) -> bool {
      py::gil_scoped_acquire gil;
      try {
        if (PyErr_CheckSignals() != 0) throw py::error_already_set();  // Ctrl-C cancels
        if (callable_.is_none()) return true;
        const py::object answer = callable_(event);
        if (answer.is_none()) return true;  // a callback that only prints continues
        const int truth = PyObject_IsTrue(answer.ptr());
        if (truth < 0) throw py::error_already_set();
        return truth != 0;
      } catch (...) {
        error_ = std::current_exception();
        return false;
      }
    };
  }

  /// Rethrows the callback's exception, if it raised one. Call with the GIL held.
  void rethrow_if_failed() const {
    if (error_) std::rethrow_exception(error_);
  }

 private:
  py::object callable_;
  std::exception_ptr error_;
};

/// The thread count of msmesh.set_threads (0: the default), applied in every call's thread.
extern std::atomic<int> g_threads;

/// Runs fn(progress_callback) with the GIL released, with the thread count of set_threads.
/// The callback's own exception takes precedence over the Cancelled it causes.
template <class Fn>
auto run_without_gil(const py::object& progress, Fn&& fn) {
  msmesh::set_threads(g_threads.load());
  ProgressBridge bridge(progress);
  const ProgressCallback callback = bridge.callback();
  try {
    auto result = [&] {
      py::gil_scoped_release release;
      return fn(callback);
    }();
    bridge.rethrow_if_failed();
    return result;
  } catch (...) {
    bridge.rethrow_if_failed();
    throw;
  }
}

inline double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// Sets denoise parameter `name` (either spelling) on `o`, checked as the set_parameter binding
/// does (bind_parameters.cpp).
void set_denoise_parameter(DenoiseOptions& o, const std::string& name, double value);

/// The iteration counts and histories of Algorithm 1 / Algorithm 2 as dict entries.
py::dict normal_report(const NormalFilterStats& r);
void add_vertex_report(py::dict& d, const VertexUpdateStats& r);

// The bindings of each area (bind_*.cpp), called once by PYBIND11_MODULE (module.cpp).
void bind_denoise(py::module_& m);
void bind_parameters(py::module_& m);
void bind_mesh(py::module_& m);
void bind_segment(py::module_& m);
void bind_inpaint(py::module_& m);
void bind_draw(py::module_& m);
void bind_statistics(py::module_& m);
void bind_report(py::module_& m);

}  // namespace msmesh::python
