#include "robot/sdf_writer.h"

#include "common/xml_escape.h"

namespace hullpack {
namespace {

std::string Element(const char* tag, double value) {
  return std::string("<") + tag + ">" + XmlNumber(value) + "</" + tag + ">";
}

}  // namespace

std::string WriteSdf(const RobotModel& model) {
  const MassProperties& m = model.mass;
  const std::string name = XmlEscape(model.name);
  std::string x;
  x += "<?xml version=\"1.0\"?>\n";
  x += "<!-- written by hullpack collision; mesh URIs are relative to this file -->\n";
  x += "<sdf version=\"1.7\">\n";
  x += "  <model name=\"" + name + "\">\n";
  x += "    <link name=\"" + name + "\">\n";
  x += "      <inertial>\n";
  x += "        <pose>" + XmlNumber(m.center[0]) + " " + XmlNumber(m.center[1]) + " " +
       XmlNumber(m.center[2]) + " 0 0 0</pose>\n";
  x += "        " + Element("mass", m.mass) + "\n";
  x += "        <inertia>" + Element("ixx", m.inertia[0]) + Element("ixy", m.inertia[3]) +
       Element("ixz", m.inertia[4]) + Element("iyy", m.inertia[1]) + Element("iyz", m.inertia[5]) +
       Element("izz", m.inertia[2]) + "</inertia>\n";
  x += "      </inertial>\n";
  x += "      <visual name=\"" + name + "_visual\">\n";
  x +=
      "        <geometry><mesh><uri>" + XmlEscape(model.visual_file) + "</uri></mesh></geometry>\n";
  x += "      </visual>\n";
  for (size_t h = 0; h < model.hull_files.size(); ++h) {
    x += "      <collision name=\"" + name + "_hull_" + std::to_string(h) + "\">\n";
    x += "        <geometry><mesh><uri>" + XmlEscape(model.hull_files[h]) +
         "</uri></mesh></geometry>\n";
    x += "      </collision>\n";
  }
  x += "    </link>\n";
  x += "  </model>\n";
  x += "</sdf>\n";
  return x;
}

}  // namespace hullpack
