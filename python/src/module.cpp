// irid._irid: the extension behind the Python package irid (python/irid/__init__.py, which
// documents the public functions). Thin: it adapts arrays and names, calls the library, and
// turns the library's exceptions into Python's: UnknownNameError → KeyError, irid::Error →
// ValueError, std::bad_alloc → MemoryError (pybind11's own), I/O failures → OSError.

#include "arrays.h"

#include <irid/error.h>
#include <irid/parallel.h>

#include <pybind11/pybind11.h>

namespace py = pybind11;

namespace irid::python {
void add_colour(py::module_& m);
void add_gamut(py::module_& m);
void add_io(py::module_& m);
void add_lut(py::module_& m);
void add_optics(py::module_& m);
void add_render(py::module_& m);
}  // namespace irid::python

PYBIND11_MODULE(_irid, m) {
    m.doc() = "irid's C++ core (use the package irid, which documents every function)";
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const irid::python::FileError& e) {
            PyErr_SetString(PyExc_OSError, e.what());
        } catch (const irid::UnknownNameError& e) {
            PyErr_SetString(PyExc_KeyError, e.what());
        } catch (const irid::Error& e) {
            PyErr_SetString(PyExc_ValueError, e.what());
        }
    });
    // The most threads= takes (irid/parallel.h), as every --threads of the command line.
    m.attr("max_threads") = irid::max_threads;
    irid::python::add_colour(m);
    irid::python::add_gamut(m);
    irid::python::add_io(m);
    irid::python::add_lut(m);
    irid::python::add_optics(m);
    irid::python::add_render(m);
}
