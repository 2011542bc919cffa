#include "batch_command.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <ostream>
#include <sstream>
#include <thread>

#include "holefill/cores.h"
#include "holefill/errors.h"
#include "holefill/mesh_format.h"
#include "outputs.h"
#include "table.h"

namespace holefill::cli {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

// One mesh of the batch and what its fill gave.
struct BatchFile {
  std::string input, output;
  int code = kOk;
  std::string messages;  // its stderr
  std::string report;    // its JSON report; empty when none was written
};

// The meshes named, a folder's own files with a mesh extension in name order (not its subfolders).
std::vector<std::string> batch_inputs(const std::vector<std::string>& named) {
  std::vector<std::string> inputs;
  for (const auto& name : named) {
    if (name == "-") throw UsageError("standard input (-) cannot be one of several meshes");
    std::error_code error;
    if (!fs::is_directory(name, error)) {
      inputs.push_back(name);
      continue;
    }
    std::vector<std::string> found;
    for (const auto& entry : fs::directory_iterator(name, error)) {
      if (entry.is_regular_file(error) && format_from_path(entry.path())) {
        found.push_back(entry.path().string());
      }
    }
    if (error) throw FileError(name, "could not be listed: " + error.message());
    std::sort(found.begin(), found.end());
    inputs.insert(inputs.end(), found.begin(), found.end());
  }
  if (inputs.empty()) throw UsageError("no .obj .off .ply or .stl files in the folders given");
  return inputs;
}

std::vector<BatchFile> plan_batch(const FillArguments& a) {
  if (a.output == "-") throw UsageError("several meshes are written into a folder, not to -o -");
  if (a.report_path == "-") throw UsageError("a batch's --report goes to a file, not to -");
  std::error_code error;
  if (fs::exists(a.output, error) && !fs::is_directory(a.output, error)) {
    throw UsageError("-o " + a.output + ": several meshes are written into a folder; " + a.output +
                     " is not one");
  }
  fs::create_directories(a.output, error);
  if (error) throw FileError(a.output, "the output folder could not be made: " + error.message());
  std::vector<BatchFile> files;
  std::map<std::string, std::string> taken;  // output -> the input written there
  for (const auto& input : batch_inputs(a.inputs)) {
    fs::path name = fs::path(input).filename();
    if (!a.format.empty()) name.replace_extension("." + a.format);
    const std::string output = (fs::path(a.output) / name).string();
    const auto [at, fresh] = taken.emplace(output, input);
    if (!fresh) {
      throw UsageError(at->second + " and " + input + " would both be written to " + output);
    }
    files.push_back({input, output, kOk, {}, {}});
  }
  return files;
}

// Fills one mesh as `holefill fill -q INPUT -o OUTPUT --report - --threads THREADS` would, its
// report and stderr kept.
void fill_one(const FillArguments& batch, unsigned threads, BatchFile& file, std::istream& in) {
  FillArguments a = batch;
  a.options.threads = a.preparation.threads = threads;
  a.input = file.input;
  a.output = file.output;
  a.report_path = "-";
  a.format.clear();
  std::ostringstream out, err;
  file.code = exit_code_of(
      [&] {
        return run_fill(a, Streams{in, out, err, Verbosity::Quiet});
      },
      err);
  file.messages = err.str();
  file.report = out.str();
}

// "filled 2 of 3 selected holes (3 in all); 1 holes remain", as a single fill's last line.
std::string fill_summary(const Json& report) {
  std::size_t filled = 0, intersecting = 0;
  for (const auto& hole : report["holes"]) {
    if (hole["filled"].get<bool>()) ++filled;
    if (hole["self_intersections"].get<std::size_t>() > 0) ++intersecting;
  }
  std::string text = "filled " + std::to_string(filled) + " of " +
                     std::to_string(report["holes"].size()) + " selected holes (" +
                     report["before"]["holes"].dump() + " in all); " +
                     report["after"]["holes"].dump() + " holes remain";
  if (intersecting) text += "; " + std::to_string(intersecting) + " patches intersect the mesh";
  return text;
}

// The line of one mesh: what its fill did, or its first error.
std::string file_line(const BatchFile& file) {
  std::string line = file.input + ": ";
  if (!file.report.empty()) {
    line += fill_summary(Json::parse(file.report)) + " -> " + file.output;
  } else {
    // The error is the last of its lines (warnings come before it, usage hints after it).
    std::string error;
    std::istringstream lines(file.messages);
    for (std::string text; std::getline(lines, text);) {
      if (text.rfind("holefill: ", 0) == 0) error = text.substr(10);
    }
    if (error.rfind(file.input + ": ", 0) == 0) error.erase(0, file.input.size() + 2);
    line += "not filled: " + error;
  }
  return line + " (exit " + std::to_string(file.code) + ")\n";
}

int severity(int code) {
  constexpr int kOrder[] = {kOk,    kPatchesIntersect, kSomeHolesNotFilled, kWriteFailed, kBadInput,
                            kUsage, kOutOfMemory,      kInternalError};
  return static_cast<int>(std::find(std::begin(kOrder), std::end(kOrder), code) - kOrder);
}

std::string total_line(const std::vector<BatchFile>& files, int worst, double seconds) {
  std::map<int, std::size_t> by_code;
  for (const auto& file : files) ++by_code[file.code];
  std::string line = "total: " + std::to_string(files.size()) + " meshes";
  for (const auto& [code, count] : by_code) {
    line += ", " + std::to_string(count) + " exit " + std::to_string(code);
  }
  return line + " in " + format("%.1f", seconds) + " s; exit " + std::to_string(worst) + "\n";
}

std::string batch_report(const std::vector<BatchFile>& files, int worst) {
  Json list = Json::array();
  for (const auto& file : files) {
    Json entry{{"input", file.input}, {"output", file.output}, {"exit_code", file.code}};
    entry["report"] = file.report.empty() ? Json(nullptr) : Json::parse(file.report);
    entry["messages"] = file.messages;
    list.push_back(std::move(entry));
  }
  const Json document{{"exit_code", worst}, {"meshes", std::move(list)}};
  return document.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

}  // namespace

unsigned threads_per_mesh(unsigned threads, unsigned jobs, unsigned cores) {
  return threads ? threads : std::max(1u, cores / std::max(1u, jobs));
}

bool is_batch(const FillArguments& a) {
  std::error_code error;
  return a.inputs.size() > 1 || (!a.output.empty() && a.output.back() == '/') ||
         fs::is_directory(a.output, error);
}

int run_batch(const FillArguments& a, const Streams& streams) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<BatchFile> files = plan_batch(a);
  std::mutex mutex;  // the streams and the next line to print
  std::vector<bool> done(files.size(), false);
  std::size_t printed = 0;
  // Lines in the meshes' order, each as soon as it and those before it are done.
  const auto finished = [&](std::size_t i) {
    const std::lock_guard lock(mutex);
    done[i] = true;
    for (; printed < files.size() && done[printed]; ++printed) {
      streams.err << files[printed].messages;
      if (streams.verbosity != Verbosity::Quiet) streams.out << file_line(files[printed]);
    }
  };
  const unsigned cores = available_cores();
  const auto jobs =
      static_cast<unsigned>(std::min<std::size_t>(a.jobs ? a.jobs : cores, files.size()));
  const unsigned threads = threads_per_mesh(a.options.threads, jobs, cores);
  std::atomic<std::size_t> next{0};
  const auto worker = [&] {
    for (std::size_t i = next++; i < files.size(); i = next++) {
      fill_one(a, threads, files[i], streams.in);
      finished(i);
    }
  };
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < jobs; ++t) pool.emplace_back(worker);
  worker();
  for (auto& thread : pool) thread.join();

  int worst = kOk;
  for (const auto& file : files) {
    if (severity(file.code) > severity(worst)) worst = file.code;
  }
  if (!a.report_path.empty()) {
    try {
      write_output(a.report_path, batch_report(files, worst), streams.out);
    } catch (const FileError& e) {
      streams.err << "holefill: " << e.what() << "; the batch's report was not written\n";
      if (severity(kWriteFailed) > severity(worst)) worst = kWriteFailed;
    }
  }
  if (streams.verbosity != Verbosity::Quiet) {
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    streams.out << total_line(files, worst, seconds);
  }
  return worst;
}

}  // namespace holefill::cli
