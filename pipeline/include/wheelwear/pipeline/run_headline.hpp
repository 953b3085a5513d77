#pragma once
/// The headline outputs of a run, read back from its results file: what `wheelwear run` reports
/// at its end and what a sweep's summary tabulates for each of its runs.

#include <map>
#include <string>

#include "wheelwear/pipeline/results_file.hpp"

namespace wheelwear::pipeline {

struct RunHeadline {
  int steps = 0;          ///< wear steps in the file (its last step's index)
  double distance = 0.0;  ///< running distance reached [m]
  bool complete = false;  ///< the run ended (its distance, or a limit it stops at)
  std::string wheel;      ///< the group of the first wheel profile ("wheel", "wheel_left", ...)
  double Sh_start = 0.0, Sh_end = 0.0;              ///< EN 15313 flange height, new and last [m]
  double Sd_start = 0.0, Sd_end = 0.0;              ///< flange thickness [m]
  double qR_start = 0.0, qR_end = 0.0;              ///< qR [m]
  double conicity_start = 0.0, conicity_end = 0.0;  ///< equivalent conicity (EN 15302)
  /// Worn cross-section of the first profile at the last step: its cumulative depth integrated
  /// along the new profile's arc length [m^2].
  double worn_area = 0.0;
  /// The states not worn over the whole run, by DroppedStates::named(): counts summed over the
  /// steps, weights as shares of the run's distance (each step's share times its distance).
  std::map<std::string, double> dropped;
  int limit_step = -1;            ///< first step at which a profile reached an in-service limit
  std::string limit_reached;      ///< what it reached ("wheel Sd 21.980 mm <= 22.000 mm")
  bool stopped_at_limit = false;  ///< the run stopped there ([limits] stop)
};

/// Reads the headline of the run in `file`; throws InputError for a file without steps.
RunHeadline read_headline(const ResultsFile& file);

}  // namespace wheelwear::pipeline
