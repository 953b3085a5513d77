// run(): a scene's wear-evolution run into an HDF5 results file, or the resume of one; Ctrl-C
// stops it after the step in progress, the file keeping every finished step.

#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include <filesystem>
#include <optional>
#include <string>

#include "bindings.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/core/version.hpp"
#include "wheelwear/pipeline/wear_run.hpp"

namespace wheelwear::python {

namespace {

py::dict summary_dict(const pipeline::RunSummary& s) {
  py::dict o;
  o["steps"] = s.steps;
  o["distance"] = s.distance;
  o["worn_area"] = s.worn_area;
  o["elapsed"] = s.elapsed;
  o["evaluations"] = s.evaluations;
  o["geometry_solves"] = s.geometry_solves;
  o["table_contacts"] = s.table_contacts;
  o["patches"] = s.patches;
  o["table_patches"] = s.table_patches;
  o["table_work_share"] = s.frictional_work > 0.0 ? s.table_work / s.frictional_work : 0.0;
  o["vehicle_solves"] = s.vehicle_solves;
  return o;
}

}  // namespace

void bind_run(py::module_& m) {
  m.def(
      "run",
      [](std::optional<std::string> scene, std::optional<std::string> output,
         std::optional<std::string> resume, bool overwrite, bool allow_hook, bool resume_stored,
         std::optional<py::function> progress, std::optional<int> threads) {
        pipeline::RunOptions options;
        options.program = std::string("wheelwear Python module ") + core::version();
        options.overwrite = overwrite;
        options.allow_hook = allow_hook;
        options.resume_stored = resume_stored;
        // After every step, on the thread that runs the loop (it released the GIL): a pending
        // Ctrl-C ends the run there, its file complete up to that step.
        options.progress = [&progress](const pipeline::RunProgress& p) {
          check_interrupt();
          if (!progress) return;
          py::gil_scoped_acquire acquire;
          (*progress)(p.step, p.distance, p.total_distance, p.elapsed);
        };
        options.warning = [](const std::string& text) {
          py::gil_scoped_acquire acquire;
          // A warnings filter may turn it into an exception: raise that.
          if (PyErr_WarnEx(PyExc_RuntimeWarning, text.c_str(), 1) < 0)
            throw py::error_already_set();
        };
        if (resume) {
          if (scene || output)
            throw InputError("resume = " + *resume +
                             ": the scene and the output come from that file; give neither "
                             "scene nor output");
          pipeline::RunSummary s;
          run_on_threads(threads, [&] { s = pipeline::resume_run(*resume, options); });
          return summary_dict(s);
        }
        if (resume_stored)
          throw InputError(
              "resume_stored: it goes with resume = FILE (a new run reads its inputs)");
        if (!output) throw InputError("output: give the results file to write, e.g. \"run.h5\"");
        pipeline::RunSummary s;
        run_on_threads(threads,
                       [&] { s = pipeline::run_scene_file(scene.value_or(""), *output, options); });
        return summary_dict(s);
      },
      py::arg("scene"), py::arg("output"), py::arg("resume"), py::arg("overwrite"),
      py::arg("allow_hook"), py::arg("resume_stored"), py::arg("progress"), py::arg("threads"));
}

}  // namespace wheelwear::python
