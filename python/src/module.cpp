// wheelwear._wheelwear: the C++ libraries for Python. The public module is the package
// python/wheelwear (numpy broadcasting, results files, docstrings); this is its engine.

#include <oneapi/tbb/global_control.h>
#include <oneapi/tbb/task_arena.h>

#include <stdexcept>

#include "bindings.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/core/version.hpp"

namespace wheelwear::python {

void run_on_threads(std::optional<int> threads, const std::function<void()>& work) {
  if (threads && *threads < 1)
    throw InputError("threads = " + std::to_string(*threads) +
                     ": give at least 1 worker thread, or None for all cores");
  py::gil_scoped_release release;
  if (!threads) {
    work();
    return;
  }
  oneapi::tbb::task_arena arena(*threads);
  arena.execute(work);
}

void check_interrupt() {
  bool pending = false;
  {
    py::gil_scoped_acquire acquire;
    if (PyErr_CheckSignals() != 0) pending = true;
  }
  if (pending) throw Interrupted{};
}

}  // namespace wheelwear::python

PYBIND11_MODULE(_wheelwear, m) {
  using namespace wheelwear::python;
  m.doc() = "The C++ engine of the wheelwear package; use the package, not this module.";
  m.attr("__version__") = std::string(wheelwear::core::version());
  // Input errors are the user's: ValueError with the command line's message. A pending signal
  // that ended a call leaves its exception set (KeyboardInterrupt for Ctrl-C).
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const wheelwear::InputError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const Interrupted&) {
      if (!PyErr_Occurred()) PyErr_SetNone(PyExc_KeyboardInterrupt);
    }
  });
  bind_creep(m);
  bind_profiles(m);
  bind_contact(m);
  bind_vehicle(m);
  bind_run(m);
}
