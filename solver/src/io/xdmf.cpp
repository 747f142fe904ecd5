#include "io/xdmf.hpp"

#include <iomanip>
#include <sstream>

namespace cellsim {
namespace {

void data_item(std::ostringstream& s, const std::string& dims, const std::string& type, int precision,
               const std::string& source) {
  s << "        <DataItem Dimensions=\"" << dims << "\" NumberType=\"" << type << "\" Precision=\"" << precision
    << "\" Format=\"HDF\">" << source << "</DataItem>\n";
}

}  // namespace

std::string xdmf_text(const std::string& kind, const std::string& h5_name, const std::vector<SnapshotInfo>& snapshots,
                      long n_particles, long n_triangles) {
  const bool wall = kind == "wall";
  const std::string n = std::to_string(n_particles);
  std::ostringstream s;
  s << std::setprecision(17);
  s << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n  <Domain>\n"
    << "    <Grid Name=\"" << kind << "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (const auto& snap : snapshots) {
    s << "     <Grid Name=\"" << kind << "\" GridType=\"Uniform\">\n"
      << "      <Time Value=\"" << snap.time_s << "\"/>\n";
    if (wall) {
      s << "      <Topology TopologyType=\"Triangle\" NumberOfElements=\"" << n_triangles << "\">\n";
      data_item(s, std::to_string(n_triangles) + " 3", "Int", 4, h5_name + ":/mesh/triangles");
    } else {
      s << "      <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << n << "\" NodesPerElement=\"1\">\n";
      data_item(s, n + " 1", "Int", 4, h5_name + ":/mesh/fluid_vertices");
    }
    s << "      </Topology>\n      <Geometry GeometryType=\"XYZ\">\n";
    data_item(s, n + " 3", "Float", 8, h5_name + ":" + snap.group + "/" + kind + "_positions");
    s << "      </Geometry>\n";
    const auto attribute = [&](const std::string& name, const std::string& type, const std::string& dims) {
      s << "      <Attribute Name=\"" << name << "\" AttributeType=\"" << type << "\" Center=\"Node\">\n";
      data_item(s, dims, "Float", 8, h5_name + ":" + snap.group + "/" + kind + "_" + name);
      s << "      </Attribute>\n";
    };
    attribute("velocities", "Vector", n + " 3");
    if (!wall) {
      attribute("mass", "Scalar", n);
      attribute("density", "Scalar", n);
      attribute("pressure", "Scalar", n);
    }
    s << "     </Grid>\n";
  }
  s << "    </Grid>\n  </Domain>\n</Xdmf>\n";
  return s.str();
}

}  // namespace cellsim
