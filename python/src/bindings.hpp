#pragma once
// The pieces of the Python module `wheelwear._wheelwear`, one file each, and what they share:
// the worker threads of a call and the check for Ctrl-C while the GIL is released.

#include <pybind11/pybind11.h>

#include <cstddef>
#include <functional>
#include <optional>

namespace wheelwear::python {

namespace py = pybind11;

void bind_creep(py::module_& m);
void bind_profiles(py::module_& m);
void bind_contact(py::module_& m);
void bind_vehicle(py::module_& m);
void bind_run(py::module_& m);

/// Thrown on a worker's side once Python has a pending signal (Ctrl-C): the call unwinds and
/// the module raises the signal's exception (KeyboardInterrupt) in its place.
struct Interrupted {};

/// Runs `work` on at most `threads` worker threads (all cores when not given) with the GIL
/// released; throws InputError for threads < 1.
void run_on_threads(std::optional<int> threads, const std::function<void()>& work);

/// With the GIL released: takes it briefly and asks Python whether a signal is pending; throws
/// Interrupted if so. Call from the thread that released the GIL only.
void check_interrupt();

}  // namespace wheelwear::python
