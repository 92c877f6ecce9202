#include "robot/urdf_writer.h"

#include "common/xml_escape.h"

namespace hullpack {

std::string WriteUrdf(const RobotModel& model) {
  const MassProperties& m = model.mass;
  const std::string name = XmlEscape(model.name);
  std::string x;
  x += "<?xml version=\"1.0\"?>\n";
  x += "<!-- written by hullpack collision; meshes are relative to this file -->\n";
  x += "<robot name=\"" + name + "\">\n";
  x += "  <link name=\"" + name + "\">\n";
  x += "    <inertial>\n";
  x += "      <origin xyz=\"" + XmlNumber(m.center[0]) + " " + XmlNumber(m.center[1]) + " " +
       XmlNumber(m.center[2]) + "\" rpy=\"0 0 0\"/>\n";
  x += "      <mass value=\"" + XmlNumber(m.mass) + "\"/>\n";
  x += "      <inertia ixx=\"" + XmlNumber(m.inertia[0]) + "\" ixy=\"" + XmlNumber(m.inertia[3]) +
       "\" ixz=\"" + XmlNumber(m.inertia[4]) + "\" iyy=\"" + XmlNumber(m.inertia[1]) + "\" iyz=\"" +
       XmlNumber(m.inertia[5]) + "\" izz=\"" + XmlNumber(m.inertia[2]) + "\"/>\n";
  x += "    </inertial>\n";
  x += "    <visual name=\"" + name + "_visual\">\n";
  x += "      <geometry><mesh filename=\"" + XmlEscape(model.visual_file) + "\"/></geometry>\n";
  x += "    </visual>\n";
  for (size_t h = 0; h < model.hull_files.size(); ++h) {
    x += "    <collision name=\"" + name + "_hull_" + std::to_string(h) + "\">\n";
    x += "      <geometry><mesh filename=\"" + XmlEscape(model.hull_files[h]) + "\"/></geometry>\n";
    x += "    </collision>\n";
  }
  x += "  </link>\n";
  x += "</robot>\n";
  return x;
}

}  // namespace hullpack
