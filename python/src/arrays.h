#pragma once

// Arrays of triples between numpy and the library: shape (..., 3), float32 or float64, kept as
// they are when C-contiguous (no copy), converted otherwise; results in a new array or in out=.

#include <irid/error.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstddef>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace irid::python {

namespace py = pybind11;

/// A file irid_io could not read or write: OSError in Python (module.cpp).
class FileError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// "(2, 3)" for messages.
inline std::string shape_text(const py::array& a) {
    std::string s = "(";
    for (py::ssize_t i = 0; i < a.ndim(); ++i) {
        s += (i ? ", " : "") + std::to_string(a.shape(i));
    }
    return s + (a.ndim() == 1 ? ",)" : ")");
}

/// Throws ValueError for a masked array (numpy.ma.MaskedArray, an ndarray subclass): its mask
/// would be silently dropped, since irid has no masked operations. A plain ndarray costs one
/// pointer comparison.
inline void refuse_masked(const py::handle& value, const char* what) {
    const auto* type = reinterpret_cast<const PyObject*>(Py_TYPE(value.ptr()));
    if (type == reinterpret_cast<const PyObject*>(py::detail::npy_api::get().PyArray_Type_)) return;
    if (!py::isinstance<py::array>(value)) return;  // lists and scalars have no mask
    // Held for the life of the process: no destructor after the interpreter has finished.
    static const py::object* const masked =
        new py::object(py::module_::import("numpy.ma").attr("MaskedArray"));
    if (PyObject_IsInstance(value.ptr(), masked->ptr()) == 1) {
        throw py::value_error(std::string(what) +
                              ": a masked array (numpy.ma); irid has no masked operations and "
                              "would drop the mask: pass a.filled(value) or a.data");
    }
}

/// `value` as a numpy array of numbers (bool, integer, unsigned or float; lists are converted).
/// Throws ValueError naming `what` for anything else (strings, objects, complex, dates), and
/// lets a MemoryError through.
inline py::array numeric_array(const py::handle& value, const char* what) {
    refuse_masked(value, what);
    if (py::isinstance<py::array>(value)) {
        py::array a = py::reinterpret_borrow<py::array>(value);
        const char kind = a.dtype().kind();
        if (kind == 'b' || kind == 'i' || kind == 'u' || kind == 'f') return a;
    }
    // numpy's own conversion (PyArray_FromAny without a dtype), keeping its exceptions.
    constexpr int ensure_array = 0x40;  // NPY_ARRAY_ENSUREARRAY
    py::array a = py::reinterpret_steal<py::array>(py::detail::npy_api::get().PyArray_FromAny_(
        value.ptr(), nullptr, 0, 0, ensure_array, nullptr));
    if (!a) {
        if (PyErr_ExceptionMatches(PyExc_MemoryError)) throw py::error_already_set();
        PyErr_Clear();
        throw py::value_error(std::string(what) + ": not an array of numbers");
    }
    const char kind = a.dtype().kind();
    if (kind != 'b' && kind != 'i' && kind != 'u' && kind != 'f') {
        throw py::value_error(std::string(what) + ": dtype " + std::string(py::str(a.dtype())) +
                              "; numbers are needed (bool, integer or float)");
    }
    return a;
}

/// Whether a numeric array holds 4-byte floats (of either byte order): the float path.
inline bool is_float32(const py::array& a) {
    return a.dtype().kind() == 'f' && a.dtype().itemsize() == 4;
}

/// A (..., k) array of T, C-contiguous (a copy when the input is not, or has another dtype).
template <class T>
struct Rows {
    py::array_t<T, py::array::c_style | py::array::forcecast> array;
    std::vector<py::ssize_t> shape;  // the whole shape, last axis k
    std::size_t count = 0;           // how many rows of k

    [[nodiscard]] std::span<const T> values() const {
        return {array.data(), static_cast<std::size_t>(array.size())};
    }
};

/// Takes `value` (numeric_array's) as rows of `k` (the last axis). Throws ValueError naming
/// `what` otherwise.
/// `value` (numeric_array's) as a C-contiguous array of T: numpy.ascontiguousarray, which makes
/// no copy for a C-contiguous array of T and raises numpy's exceptions (MemoryError) for a
/// conversion that cannot be made.
template <class T>
py::array_t<T, py::array::c_style | py::array::forcecast> contiguous_of(const py::handle& value,
                                                                         const char* what) {
    using Contiguous = py::array_t<T, py::array::c_style | py::array::forcecast>;
    refuse_masked(value, what);
    if (py::isinstance<py::array_t<T>>(value) &&
        (py::reinterpret_borrow<py::array>(value).flags() & py::array::c_style)) {
        return py::reinterpret_borrow<Contiguous>(value);  // already right: no call into numpy
    }
    // Held for the life of the process: no destructor after the interpreter has finished.
    static const py::object* const contiguous =
        new py::object(py::module_::import("numpy").attr("ascontiguousarray"));
    return py::reinterpret_borrow<py::array_t<T, py::array::c_style | py::array::forcecast>>(
        (*contiguous)(numeric_array(value, what), py::dtype::of<T>()));
}

template <class T>
Rows<T> rows_of(const py::handle& value, py::ssize_t k, const char* what) {
    Rows<T> r;
    r.array = contiguous_of<T>(value, what);
    if (r.array.ndim() < 1 || r.array.shape(r.array.ndim() - 1) != k) {
        throw py::value_error(std::string(what) + ": shape " + shape_text(r.array) +
                              "; expected (..., " + std::to_string(k) + ")");
    }
    for (py::ssize_t i = 0; i < r.array.ndim(); ++i) r.shape.push_back(r.array.shape(i));
    r.count = static_cast<std::size_t>(r.array.size() / k);
    return r;
}

/// The result array: `out` when given (checked: a C-contiguous, writeable ndarray of T with
/// exactly `shape`), else a new one.
template <class T>
py::array_t<T> result_array(const py::object& out, const std::vector<py::ssize_t>& shape) {
    if (out.is_none()) return py::array_t<T>(shape);
    if (!py::isinstance<py::array>(out)) throw py::value_error("out: not a numpy array");
    py::array a = py::reinterpret_borrow<py::array>(out);
    const char* dtype = std::is_same_v<T, float> ? "float32" : "float64";
    if (!py::isinstance<py::array_t<T>>(out)) {
        throw py::value_error(std::string("out: dtype ") + std::string(py::str(a.dtype())) +
                              "; this call writes " + dtype);
    }
    bool same = a.ndim() == static_cast<py::ssize_t>(shape.size());
    for (std::size_t i = 0; same && i < shape.size(); ++i) same = a.shape(static_cast<py::ssize_t>(i)) == shape[i];
    if (!same) {
        std::string expected = "(";
        for (std::size_t i = 0; i < shape.size(); ++i) expected += (i ? ", " : "") + std::to_string(shape[i]);
        throw py::value_error("out: shape " + shape_text(a) + "; expected " + expected +
                              (shape.size() == 1 ? ",)" : ")"));
    }
    if (!(a.flags() & py::array::c_style)) throw py::value_error("out: not C-contiguous");
    if (!a.writeable()) throw py::value_error("out: read-only");
    return py::reinterpret_borrow<py::array_t<T>>(out);
}

template <class T>
std::span<T> mutable_values(py::array_t<T>& a) {
    return {a.mutable_data(), static_cast<std::size_t>(a.size())};
}

}  // namespace irid::python
