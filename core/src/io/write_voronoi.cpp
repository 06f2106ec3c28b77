// Triangle's .v.node / .v.edge texts of a mesh's dual (output/voronoi.cpp computes it).
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <ostream>
#include <string>

#include "ruppert/ruppert.h"
#include "io/text_out.h"
#include "cold_code.h"

RUPPERT_COLD_BEGIN

namespace ruppert {

namespace {

using detail::TextOut;
using detail::toStream;
using detail::toText;

std::string real(double v) {
  if (!std::isfinite(v)) throw Error(ErrorCode::Internal, "cannot write a non-finite Voronoi coordinate");
  return detail::realText(v);
}

void printNode(TextOut& out, const Voronoi& v, const Mesh& mesh) {
  const std::size_t base = mesh.indexBase == 1 ? 1 : 0, n = v.points.size() / 2;
  out << n << " 2 0 0\n";
  for (std::size_t i = 0; i < n; ++i) out << (i + base) << ' ' << real(v.points[2 * i]) << ' ' << real(v.points[2 * i + 1]) << '\n';
}

void printEdge(TextOut& out, const Voronoi& v, const Mesh& mesh) {
  const std::int64_t base = mesh.indexBase == 1 ? 1 : 0;
  const std::size_t n = v.edges.size() / 2;
  out << n << " 0\n";
  for (std::size_t e = 0; e < n; ++e) {
    out << (std::int64_t(e) + base) << ' ' << (v.edges[2 * e] + base) << ' ';
    if (v.edges[2 * e + 1] < 0) out << "-1 " << real(v.rayDirections[2 * e]) << ' ' << real(v.rayDirections[2 * e + 1]) << '\n';
    else out << (v.edges[2 * e + 1] + base) << '\n';
  }
}

}  // namespace


void writeVoronoiNode(std::ostream& out, const Voronoi& v, const Mesh& mesh) {
  toStream(out, ".v.node", [&](TextOut& t) { printNode(t, v, mesh); });
}
void writeVoronoiEdge(std::ostream& out, const Voronoi& v, const Mesh& mesh) {
  toStream(out, ".v.edge", [&](TextOut& t) { printEdge(t, v, mesh); });
}
std::string toVoronoiNode(const Voronoi& v, const Mesh& mesh) { return toText([&](TextOut& t) { printNode(t, v, mesh); }); }
std::string toVoronoiEdge(const Voronoi& v, const Mesh& mesh) { return toText([&](TextOut& t) { printEdge(t, v, mesh); }); }

}  // namespace ruppert
RUPPERT_COLD_END
