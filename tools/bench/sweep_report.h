// What the sweep writes: the CSV (one row per mesh x point), the SVG plots (error against run time,
// size against error) and a Markdown summary that shows the plots and tables of medians.
#ifndef HULLPACK_TOOLS_BENCH_SWEEP_REPORT_H_
#define HULLPACK_TOOLS_BENCH_SWEEP_REPORT_H_

#include <string>
#include <utility>
#include <vector>

#include "bench/sweep.h"
#include "common/status.h"

namespace hullpack {

// The CSV columns, in order.
const std::vector<std::string>& SweepCsvColumns();

// Header line and one line per row; "not applicable" (-1) fields are empty.
std::string SweepCsv(const std::vector<SweepRow>& rows);

// (file name, SVG document) of every plot the rows can fill; a plot without any point is left out.
std::vector<std::pair<std::string, std::string>> SweepPlots(const SweepResult& result,
                                                            const SweepOptions& options);

// The Markdown summary; `command` is the command line that made it, `plots` the plot files to show.
std::string SweepSummary(const SweepResult& result, const SweepOptions& options,
                         const std::string& command, const std::vector<std::string>& plots);

// Writes sweep.csv, summary.md and the plots into `folder` (created if missing).
Status WriteSweepOutputs(const SweepResult& result, const SweepOptions& options,
                         const std::string& folder, const std::string& command);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_BENCH_SWEEP_REPORT_H_
