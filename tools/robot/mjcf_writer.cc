#include "robot/mjcf_writer.h"

#include "common/xml_escape.h"

namespace hullpack {

std::string WriteMjcf(const RobotModel& model) {
  const MassProperties& m = model.mass;
  const std::string name = XmlEscape(model.name);
  std::string x;
  x += "<?xml version=\"1.0\"?>\n";
  x += "<!-- written by hullpack collision; mesh files are relative to this file -->\n";
  x += "<mujoco model=\"" + name + "\">\n";
  x += "  <asset>\n";
  x += "    <mesh name=\"" + name + "_visual\" file=\"" + XmlEscape(model.visual_file) + "\"/>\n";
  for (size_t h = 0; h < model.hull_files.size(); ++h) {
    x += "    <mesh name=\"" + name + "_hull_" + std::to_string(h) + "\" file=\"" +
         XmlEscape(model.hull_files[h]) + "\" maxhullvert=\"" +
         std::to_string(model.max_hull_vertices) + "\"/>\n";
  }
  x += "  </asset>\n";
  x += "  <worldbody>\n";
  x += "    <body name=\"" + name + "\">\n";
  x += "      <freejoint name=\"" + name + "_free\"/>\n";
  x += "      <inertial pos=\"" + XmlNumber(m.center[0]) + " " + XmlNumber(m.center[1]) + " " +
       XmlNumber(m.center[2]) + "\" mass=\"" + XmlNumber(m.mass) + "\" fullinertia=\"" +
       XmlNumber(m.inertia[0]) + " " + XmlNumber(m.inertia[1]) + " " + XmlNumber(m.inertia[2]) +
       " " + XmlNumber(m.inertia[3]) + " " + XmlNumber(m.inertia[4]) + " " +
       XmlNumber(m.inertia[5]) + "\"/>\n";
  x += "      <geom name=\"" + name + "_visual\" type=\"mesh\" mesh=\"" + name +
       "_visual\" contype=\"0\" conaffinity=\"0\" group=\"2\"/>\n";
  for (size_t h = 0; h < model.hull_files.size(); ++h) {
    const std::string hull = name + "_hull_" + std::to_string(h);
    x += "      <geom name=\"" + hull + "\" type=\"mesh\" mesh=\"" + hull + "\" group=\"3\"/>\n";
  }
  x += "    </body>\n";
  x += "  </worldbody>\n";
  x += "</mujoco>\n";
  return x;
}

}  // namespace hullpack
