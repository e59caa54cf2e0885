// msmesh._core: the pybind11 bindings under the pure-Python package msmesh (python/msmesh),
// one file per area (bind_*.cpp; shared pieces in bindings.h).
#include "bindings.h"

PYBIND11_MODULE(_core, m) {
  using namespace msmesh::python;
  m.doc() = "Compiled core of msmesh; use the functions of the msmesh package, which check their inputs.";
  register_exceptions(m);
  bind_denoise(m);
  bind_parameters(m);
  bind_mesh(m);
  bind_segment(m);
  bind_inpaint(m);
  bind_draw(m);
  bind_statistics(m);
  bind_report(m);
}
