// Gmsh writers: MSH 4.1 ASCII (what `.msh` means for write_tet_mesh) and MSH 2.2 ASCII.
#include <algorithm>

#include "io/atomic_file.hpp"
#include "io/write_mesh.hpp"

namespace cmx::io {
namespace {

// One discrete volume (tag 1) holding everything, with the points' bounding box.
void write_entities41(std::ostream& out, const std::vector<DoublePoint>& points) {
  DoublePoint low{0, 0, 0}, high{0, 0, 0};
  for (std::size_t i = 0; i < points.size(); ++i)
    for (std::size_t k = 0; k < 3; ++k) {
      low[k] = i ? std::min(low[k], points[i][k]) : points[i][k];
      high[k] = i ? std::max(high[k], points[i][k]) : points[i][k];
    }
  out << "$Entities\n0 0 0 1\n1 ";
  detail::write_point(out, low);
  out << ' ';
  detail::write_point(out, high);
  out << " 0 0\n$EndEntities\n";
}

void write_nodes41(std::ostream& out, const std::vector<DoublePoint>& points) {
  const std::size_t n = points.size();
  out << "$Nodes\n" << (n ? 1 : 0) << ' ' << n << ' ' << (n ? 1 : 0) << ' ' << n << '\n';
  if (n) {
    out << "3 1 0 " << n << '\n';
    for (std::size_t i = 0; i < n; ++i) out << i + 1 << '\n';
    for (const auto& p : points) {
      detail::write_point(out, p);
      out << '\n';
    }
  }
  out << "$EndNodes\n";
}

void write_elements41(std::ostream& out, const std::vector<Tet>& tets) {
  const std::size_t m = tets.size();
  out << "$Elements\n" << (m ? 1 : 0) << ' ' << m << ' ' << (m ? 1 : 0) << ' ' << m << '\n';
  if (m) out << "3 1 4 " << m << '\n';
  for (std::size_t i = 0; i < m; ++i) {
    const auto& t = tets[i];
    out << i + 1 << ' ' << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << ' ' << t[3] + 1 << '\n';
  }
  out << "$EndElements\n";
}

// A $NodeData or $ElementData header: the view's name, time 0, time step 0, components, count.
void write_data_header(std::ostream& out, const char* section, const std::string& name, int components, std::size_t count) {
  out << '$' << section << "\n1\n\"" << name << "\"\n1\n0\n3\n0\n" << components << '\n' << count << '\n';
}

void write_fields41(std::ostream& out, const DisplayFields& fields) {
  for (const auto& f : fields.point_vectors) {
    write_data_header(out, "NodeData", f.name, 3, f.values.size());
    for (std::size_t i = 0; i < f.values.size(); ++i) {
      out << i + 1 << ' ';
      detail::write_point(out, f.values[i]);
      out << '\n';
    }
    out << "$EndNodeData\n";
  }
  for (const auto& f : fields.cell_scalars) {
    write_data_header(out, "ElementData", f.name, 1, f.values.size());
    for (std::size_t i = 0; i < f.values.size(); ++i) out << i + 1 << ' ' << format_double(f.values[i]) << '\n';
    out << "$EndElementData\n";
  }
}

}  // namespace

void write_gmsh41(const std::string& path, const std::vector<DoublePoint>& points, const std::vector<Tet>& tets,
                  const DisplayFields& fields) {
  detail::check_writable(path, points, tets);
  detail::check_fields(path, points.size(), tets.size(), fields);
  write_file_atomically(path, [&](std::ostream& out) {
    out << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
    write_entities41(out, points);
    write_nodes41(out, points);
    write_elements41(out, tets);
    write_fields41(out, fields);
  });
}

void write_gmsh(const std::string& path, const std::vector<DoublePoint>& points, const std::vector<Tet>& tets) {
  detail::check_writable(path, points, tets);
  write_file_atomically(path, [&](std::ostream& out) {
    out << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n" << points.size() << '\n';
    for (std::size_t i = 0; i < points.size(); ++i) {
      out << i + 1 << ' ';
      detail::write_point(out, points[i]);
      out << '\n';
    }
    out << "$EndNodes\n$Elements\n" << tets.size() << '\n';
    // Two tags (physical 1, elementary 1): what Gmsh itself writes and every reader expects.
    for (std::size_t i = 0; i < tets.size(); ++i) {
      const auto& t = tets[i];
      out << i + 1 << " 4 2 1 1 " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << ' ' << t[3] + 1 << '\n';
    }
    out << "$EndElements\n";
  });
}

}  // namespace cmx::io
