#include "wheelwear/pipeline/sweep.hpp"

#include <H5public.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <toml++/toml.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <mutex>
#include <sstream>
#include <utility>

#include "wheelwear/core/input_error.hpp"
#include "wheelwear/core/text.hpp"
#include "wheelwear/pipeline/results_file.hpp"
#include "wheelwear/pipeline/scene.hpp"

namespace wheelwear::pipeline {

namespace fs = std::filesystem;

namespace {

std::string where(const toml::node& node, std::string_view key) {
  return "sweep line " + std::to_string(node.source().begin.line) + ": " + std::string(key);
}

// A scalar value as the sweep file writes it ("0.3", "1e3", "\"S1002\""): its own source text,
// so that the summary shows the values as the user typed them.
std::string source_of(const toml::node& value, const std::string& key,
                      const std::vector<std::string>& lines) {
  if (!(value.is_number() || value.is_string() || value.is_boolean()))
    throw InputError(where(value, key) +
                     ": each value to vary must be a number, a string or a boolean");
  const toml::source_region& r = value.source();
  // toml++ counts columns in characters: only a line of ASCII maps them to bytes.
  const auto ascii = [](const std::string& line) {
    return std::all_of(line.begin(), line.end(), [](char c) { return (c & 0x80) == 0; });
  };
  if (r.begin.line == r.end.line && r.begin.line >= 1 && r.begin.line <= lines.size() &&
      r.end.column > r.begin.column && ascii(lines[r.begin.line - 1])) {
    const std::string& line = lines[r.begin.line - 1];
    const std::size_t from = r.begin.column - 1, length = r.end.column - r.begin.column;
    if (from + length <= line.size()) return line.substr(from, length);
  }
  std::ostringstream out;
  value.visit([&out](const auto& v) { out << toml::toml_formatter{v}; });
  return out.str();
}

// The runs of `values` (one list per key): every combination (grid, the last key varying
// fastest) or the i-th value of every list (zip).
std::vector<std::vector<std::string>> combine(const std::vector<std::vector<std::string>>& values,
                                              bool grid) {
  std::vector<std::vector<std::string>> runs;
  if (!grid) {
    for (std::size_t i = 0; i < values.front().size(); ++i) {
      std::vector<std::string> run;
      for (const auto& list : values) run.push_back(list[i]);
      runs.push_back(std::move(run));
    }
    return runs;
  }
  runs.emplace_back();
  for (const auto& list : values) {
    std::vector<std::vector<std::string>> next;
    for (const auto& run : runs)
      for (const std::string& value : list) {
        next.push_back(run);
        next.back().push_back(value);
      }
    runs = std::move(next);
  }
  return runs;
}

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::string number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.9g", value);
  return buffer;
}

// A change over the run's distance, per 10^5 km.
double per_1e5_km(double change, double distance) {
  return distance > 0.0 ? change * 1e8 / distance : std::nan("");
}

std::string summary_csv(const Sweep& sweep, const std::vector<SweepRow>& rows) {
  std::ostringstream out;
  const std::vector<std::string> columns = sweep_summary_columns(sweep);
  for (std::size_t c = 0; c < columns.size(); ++c) out << (c ? "," : "") << csv_field(columns[c]);
  out << '\n';
  for (const SweepRow& row : rows) {
    std::vector<std::string> cells{std::to_string(row.index + 1),
                                   sweep_run_file(sweep, row.index).filename().string()};
    for (const std::string& value : sweep.runs[row.index]) cells.push_back(value);
    cells.push_back(row.status);
    if (row.has_headline) {
      const RunHeadline& h = row.headline;
      for (double v : {double(h.steps), h.distance, h.Sd_start, h.Sd_end, h.Sh_start, h.Sh_end,
                       h.qR_start, h.qR_end, h.conicity_start, h.conicity_end,
                       per_1e5_km(h.Sd_end - h.Sd_start, h.distance),
                       per_1e5_km(h.Sh_end - h.Sh_start, h.distance),
                       per_1e5_km(h.qR_end - h.qR_start, h.distance), h.worn_area,
                       per_1e5_km(h.worn_area, h.distance), h.dropped.at("dropped_patches_weight")})
        cells.push_back(number(v));
      cells.push_back(h.limit_reached);
    } else {
      cells.resize(columns.size() - 1);
    }
    cells.push_back(number(row.seconds));
    for (std::size_t c = 0; c < cells.size(); ++c) out << (c ? "," : "") << csv_field(cells[c]);
    out << '\n';
  }
  return out.str();
}

}  // namespace

Sweep read_sweep(const fs::path& file) {
  const std::string text = core::read_text_file(file);
  toml::table root;
  try {
    root = toml::parse(text, std::string_view("sweep"));
  } catch (const toml::parse_error& error) {
    throw InputError(file.string() + ": sweep line " + std::to_string(error.source().begin.line) +
                     ": " + std::string(error.description()));
  }
  std::vector<std::string> lines;
  {
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
  }
  Sweep s;
  s.file = fs::absolute(file);
  const fs::path folder = s.file.parent_path();
  bool grid = true;
  const toml::table* vary = nullptr;
  for (const auto& [k, node] : root) {
    const std::string key(k.str());
    if (key == "scene" && node.is_string()) {
      s.base_scene = folder / *node.value<std::string>();
    } else if (key == "output_dir" && node.is_string()) {
      s.output_dir = folder / *node.value<std::string>();
    } else if (key == "combine" && node.is_string()) {
      const std::string how = *node.value<std::string>();
      if (how != "grid" && how != "zip")
        throw InputError(file.string() + ": " + where(node, key) + " = \"" + how +
                         "\": use \"grid\" (every combination) or \"zip\" (the i-th values "
                         "together)");
      grid = how == "grid";
    } else if (key == "vary" && node.is_table()) {
      vary = node.as_table();
    } else {
      throw InputError(file.string() + ": " + where(node, key) +
                       ": unknown key or wrong type; a sweep has scene = \"FILE\", output_dir = "
                       "\"FOLDER\", combine = \"grid\" | \"zip\" and a [vary] table");
    }
  }
  if (s.base_scene.empty())
    throw InputError(file.string() + ": no scene = \"FILE\": name the base scene to vary");
  if (s.output_dir.empty()) s.output_dir = folder / (s.file.stem().string() + "_runs");
  if (!vary || vary->empty())
    throw InputError(file.string() +
                     ": no [vary] table: give the scene keys to vary, e.g. \"contact.friction\" = "
                     "[0.25, 0.3]");
  // In the order the file lists them (a toml++ table iterates its keys sorted): the runs, their
  // numbers and the summary's columns follow the file.
  std::vector<std::pair<std::string, const toml::node*>> entries;
  for (const auto& [k, node] : *vary) entries.emplace_back(std::string(k.str()), &node);
  std::sort(entries.begin(), entries.end(), [](const auto& a, const auto& b) {
    const toml::source_position &pa = a.second->source().begin, &pb = b.second->source().begin;
    return pa.line != pb.line ? pa.line < pb.line : pa.column < pb.column;
  });
  std::vector<std::vector<std::string>> values;
  for (const auto& [key, entry] : entries) {
    const toml::node& node = *entry;
    const toml::array* list = node.as_array();
    if (!list || list->empty())
      throw InputError(file.string() + ": " + where(node, key) +
                       ": give a non-empty list of values, e.g. [0.25, 0.3]");
    s.keys.push_back(key);
    values.emplace_back();
    for (const toml::node& value : *list) values.back().push_back(source_of(value, key, lines));
    if (!grid && values.back().size() != values.front().size())
      throw InputError(file.string() + ": " + where(node, key) +
                       ": combine = \"zip\" takes lists "
                       "of one length; this has " +
                       std::to_string(values.back().size()) + ", the first " +
                       std::to_string(values.front().size()));
  }
  s.runs = combine(values, grid);
  return s;
}

std::string sweep_scene_text(const Sweep& sweep, std::string_view base_text, std::size_t index) {
  toml::table root;
  try {
    root = toml::parse(base_text, std::string_view("scene"));
  } catch (const toml::parse_error& error) {
    throw InputError(sweep.base_scene.string() + ": scene line " +
                     std::to_string(error.source().begin.line) + ": " +
                     std::string(error.description()));
  }
  for (std::size_t k = 0; k < sweep.keys.size(); ++k) {
    const std::string& key = sweep.keys[k];
    toml::table* table = &root;
    std::size_t from = 0;
    for (std::size_t dot; (dot = key.find('.', from)) != std::string::npos; from = dot + 1) {
      const std::string part = key.substr(from, dot - from);
      toml::node* child = table->get(part);
      if (!child) child = &table->insert_or_assign(part, toml::table{}).first->second;
      if (!child->is_table())
        throw InputError("sweep key " + key + ": " + part +
                         " is not a table of the scene; vary keys of its tables");
      table = child->as_table();
    }
    toml::table value;
    try {
      value = toml::parse("v = " + sweep.runs[index][k]);
    } catch (const toml::parse_error& error) {
      throw InputError("sweep key " + key + " = " + sweep.runs[index][k] + ": " +
                       std::string(error.description()));
    }
    table->insert_or_assign(key.substr(from), *value.get("v"));
  }
  std::ostringstream out;
  out << toml::toml_formatter{root} << '\n';
  return out.str();
}

fs::path sweep_run_file(const Sweep& sweep, std::size_t index) {
  char name[32];
  std::snprintf(name, sizeof name, "run_%04zu.h5", index + 1);
  return sweep.output_dir / name;
}

std::vector<std::string> sweep_summary_columns(const Sweep& sweep) {
  std::vector<std::string> c{"run", "file"};
  for (const std::string& key : sweep.keys) c.push_back(key);
  for (const char* name :
       {"status", "steps", "distance_m", "Sd_start_m", "Sd_end_m", "Sh_start_m", "Sh_end_m",
        "qR_start_m", "qR_end_m", "conicity_start", "conicity_end", "Sd_change_per_1e5km_m",
        "Sh_change_per_1e5km_m", "qR_change_per_1e5km_m", "worn_area_m2", "worn_area_per_1e5km_m2",
        "not_worn_share", "limit_reached", "seconds"})
    c.emplace_back(name);
  return c;
}

namespace {

// Runs or resumes run `i` into `file`, or leaves a complete one; the row's status says which.
void run_one(const Sweep& sweep, std::size_t i, const Scene& scene, const std::string& text,
             const fs::path& base_folder, const RunOptions& options, SweepRow& row) {
  const fs::path file = sweep_run_file(sweep, i);
  if (!fs::exists(file)) {
    run_scene(scene, text, base_folder, false, file, options);
    row.status = "done";
    return;
  }
  const ResultsFile existing = ResultsFile::read(file);
  if (existing.scene_text() != text)
    throw InputError(file.string() +
                     " holds a run of another scene (the sweep's values changed "
                     "since it was written): move it away, or give the sweep another output_dir");
  // No step yet (stopped while it started), some steps, or stopped while it ended (its last
  // step named, not yet consolidated): resume_run takes each on; a complete file stays as it is.
  if (existing.completed_steps() > 0 && existing.has("/final")) {
    row.headline = read_headline(existing);
    row.has_headline = row.headline.complete;
    if (row.headline.complete) {
      row.status = "skipped";
      return;
    }
  }
  try {
    resume_run(file, options);
  } catch (const InputError&) {
    // Finished while it ended: resume_run completes the file and then says it is complete.
    if (!ResultsFile::read(file).has("/final")) throw;
  }
  row.status = "done";
}

// The headline of `row`'s results file where it has one and the row holds none yet (a skipped
// run's was read to skip it); a file without one leaves the row without, its status says why.
void read_row_headline(const Sweep& sweep, SweepRow& row) {
  try {
    const fs::path file = sweep_run_file(sweep, row.index);
    if (!row.has_headline && fs::exists(file)) {
      row.headline = read_headline(ResultsFile::read(file));
      row.has_headline = true;
    }
  } catch (const std::exception&) {
    row.has_headline = false;
  }
}

// Whether every process of `group` has its runs' scenes: a process that refused one (`refused`)
// stops them all. Process 0 keeps its own exception, or gets the first other process's reason
// as an InputError naming it; the others are left with an exception of their own.
void agree_to_start(ProcessGroup& group, std::exception_ptr& refused) {
  // "+" and nothing: ready; "-" and the reason: refused (a reason may be empty).
  std::string answer = "+";
  if (refused) {
    answer = "-";
    try {
      std::rethrow_exception(refused);
    } catch (const std::exception& e) {
      answer += e.what();
    } catch (...) {
      answer += "an unknown error";
    }
  }
  std::string first;  // "+" where all are ready, else "-" and the first refusal's reason
  const std::vector<std::string> answers = group.gather(answer);
  if (group.rank() == 0) {
    first = "+";
    for (std::size_t r = 0; r < answers.size() && first == "+"; ++r)
      if (answers[r].starts_with("-"))
        first = r == 0 ? answers[r] : "-process " + std::to_string(r) + ": " + answers[r].substr(1);
  }
  group.broadcast(first);
  if (first != "+" && !refused) refused = std::make_exception_ptr(InputError(first.substr(1)));
}

// The rows of the runs of the other processes to process 0 (their status and time; their
// headlines process 0 reads from their files). Returns whether this process is process 0.
bool gather_rows(ProcessGroup& group, const std::vector<std::size_t>& mine,
                 std::vector<SweepRow>& rows) {
  std::ostringstream out;
  for (std::size_t i : mine) {
    const SweepRow& row = rows[i];
    out << i << '\t' << std::hexfloat << row.seconds << '\t' << row.status.size() << '\t'
        << row.status;
  }
  const std::vector<std::string> parts = group.gather(out.str());
  if (group.rank() != 0) return false;
  for (std::size_t r = 1; r < parts.size(); ++r) {
    std::istringstream in(parts[r]);
    std::size_t i = 0, length = 0;
    std::string seconds;
    while (in >> i && std::getline(in.ignore(1), seconds, '\t') && in >> length) {
      in.ignore(1);
      SweepRow& row = rows.at(i);
      row.index = i;
      row.seconds = std::strtod(seconds.c_str(), nullptr);
      row.status.resize(length);
      in.read(row.status.data(), static_cast<std::streamsize>(length));
    }
  }
  return true;
}

bool hdf5_is_threadsafe() {
  hbool_t safe = 0;
  return H5is_library_threadsafe(&safe) >= 0 && safe;
}

}  // namespace

std::vector<SweepRow> run_sweep(const Sweep& sweep, const SweepOptions& options) {
  // Every run's scene is checked before the first run starts, and kept for its run.
  std::vector<std::string> texts;
  std::vector<Scene> scenes;
  fs::path base_folder;
  std::exception_ptr refused;
  try {
    const std::string base_text = core::read_text_file(sweep.base_scene);
    base_folder = fs::absolute(sweep.base_scene).parent_path();
    // The base scene on its own first, so that its own mistakes point at its own lines.
    (void)parse_scene(base_text, base_folder);
    for (std::size_t i = 0; i < sweep.runs.size(); ++i) {
      texts.push_back(sweep_scene_text(sweep, base_text, i));
      try {
        scenes.push_back(parse_scene(texts.back(), base_folder));
      } catch (const InputError& e) {
        std::string values;
        for (std::size_t k = 0; k < sweep.keys.size(); ++k)
          values += (k ? ", " : "") + sweep.keys[k] + " = " + sweep.runs[i][k];
        throw InputError(sweep.file.string() + ": run " + std::to_string(i + 1) + " (" + values +
                         "): " + e.what());
      }
    }
    fs::create_directories(sweep.output_dir);
  } catch (...) {
    refused = std::current_exception();
  }
  // Over several processes all go on, or all stop: one refusing alone would leave the others
  // waiting for it at the end.
  if (options.group && options.group->size() > 1) agree_to_start(*options.group, refused);
  if (refused) std::rethrow_exception(refused);
  std::vector<SweepRow> rows(sweep.runs.size());
  std::mutex report;
  std::size_t done = 0;
  const auto one = [&](std::size_t i) {
    SweepRow& row = rows[i];
    row.index = i;
    const auto start = std::chrono::steady_clock::now();
    try {
      // Isolated: a thread waiting inside this run takes no other run's work meanwhile (which
      // would hold this one up and count in its time).
      tbb::this_task_arena::isolate(
          [&] { run_one(sweep, i, scenes[i], texts[i], base_folder, options.run, row); });
    } catch (const std::exception& e) {
      row.status = std::string("failed: ") + e.what();
    }
    row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    read_row_headline(sweep, row);
    const std::lock_guard lock(report);
    ++done;
    if (options.finished) options.finished(row, done, rows.size());
  };
  // In a job of several processes each takes every size-th run; process 0 writes the summary.
  const int rank = options.group ? options.group->rank() : 0;
  const int size = options.group ? options.group->size() : 1;
  std::vector<std::size_t> mine;
  for (std::size_t i = static_cast<std::size_t>(rank); i < rows.size();
       i += static_cast<std::size_t>(size))
    mine.push_back(i);
  // Runs write their own files at once only where the HDF5 library is built thread-safe
  // (Debian's is); otherwise one after the other, each still parallel inside.
  if (hdf5_is_threadsafe()) {
    tbb::parallel_for(std::size_t{0}, mine.size(), std::size_t{1},
                      [&](std::size_t k) { one(mine[k]); });
  } else {
    for (std::size_t i : mine) one(i);
  }
  if (size > 1 && !gather_rows(*options.group, mine, rows)) return rows;
  if (size > 1)
    for (std::size_t i = 0; i < rows.size(); ++i) {
      if (static_cast<int>(i % static_cast<std::size_t>(size)) == 0) continue;
      read_row_headline(sweep, rows[i]);
      ++done;
      if (options.finished) options.finished(rows[i], done, rows.size());
    }
  core::write_file_atomically(sweep.output_dir / "summary.csv", summary_csv(sweep, rows));
  return rows;
}

}  // namespace wheelwear::pipeline
