// Topology and repair reports as text for people and as JSON for programs.
#ifndef HULLPACK_TOOLS_MESH_REPORT_FORMAT_H_
#define HULLPACK_TOOLS_MESH_REPORT_FORMAT_H_

#include <string>
#include <vector>

#include "mesh/repair.h"
#include "mesh/topology.h"

namespace hullpack {

// One line per aspect, without trailing newlines, numbers to 6 significant digits, e.g.
//   "triangles: 12 (0 degenerate, 0 duplicate, 0 opposite-winding pairs)"
//   "closed: yes, genus 0"
//   "volume: 1 (closed components only)"
std::vector<std::string> FormatTopologyReport(const TopologyReport& report);

// A single JSON object with every field of the report under its C++ name, plus "manifold"
// (no non-manifold edge or vertex). genus is -1 when unknown. Numbers round-trip exactly.
std::string TopologyReportToJson(const TopologyReport& report);

// A single JSON object with every counter of the repair report under its C++ name.
std::string RepairReportToJson(const RepairReport& report);

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_MESH_REPORT_FORMAT_H_
