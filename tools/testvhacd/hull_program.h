// Pieces shared by the decomposition programs (testVHACD, testHACD): the file options, reading the
// input, the progress line and log file, the JSON report and the hull scene writer.
#ifndef HULLPACK_TOOLS_TESTVHACD_HULL_PROGRAM_H_
#define HULLPACK_TOOLS_TESTVHACD_HULL_PROGRAM_H_

#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "common/cli_args.h"
#include "vhacd/vhacd.h"

namespace hullpack {

// One progress line on stderr ("\r" updates) and, with a path, every log message to a file.
class ProgressLine : public vhacd::Observer {
 public:
  explicit ProgressLine(const std::string& log_path);
  bool log_ok() const { return log_.good(); }
  void OnProgress(double overall, double stage, double operation, const char* stage_name,
                  const char* operation_name) override;
  void OnLog(const char* message) override;

 private:
  std::ofstream log_;
  int last_ = -1;
  std::string last_stage_;
};

std::string JsonNumber(double v);

// The JSON report of a decomposition (`method`: "vhacd" or "hacd"). False when it cannot be
// written.
bool WriteDecompositionReport(const std::string& path, const std::string& input,
                              const std::string& method, const vhacd::Result& r);

// Writes the hulls as a scene with one mesh per hull (format from the extension). "" on success,
// else the error.
std::string WriteHullScene(const vhacd::Result& r, const std::string& output);

// Reads every mesh of `input` (node transforms applied) as one soup. "" on success, else the error.
std::string ReadSoup(const std::string& input, std::vector<double>* points,
                     std::vector<uint32_t>* indices);

// Declares the options every decomposition program has: INPUT, -o/--output, --report, --log.
void AddFileOptions(CliArgs* cli, std::vector<std::string>* inputs, std::string* output,
                    std::string* report_path, std::string* log_path);

// ReadSoup, then the "input:" line on stdout; false after naming the error on stderr.
bool ReadInput(const char* program, const std::string& input, std::vector<double>* points,
               std::vector<uint32_t>* indices);

// A failed decomposition: the status on stderr and, with a path, the report. Returns exit code 1.
int ReportFailure(const char* program, const std::string& input, const std::string& report_path,
                  const std::string& method, const vhacd::Result& r);

// A successful decomposition: the report and the hulls where paths are given, a "wrote" line for
// each. Returns the exit code.
int WriteResults(const char* program, const std::string& input, const std::string& report_path,
                 const std::string& output, const std::string& method, const vhacd::Result& r);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_TESTVHACD_HULL_PROGRAM_H_
