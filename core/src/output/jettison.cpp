#include "output/jettison.h"
#include "cold_code.h"

RUPPERT_COLD_BEGIN

namespace ruppert::detail {

namespace {

// Keeps the entries (blocks of `width`) of the points that stay, in order.
template <class T>
void compact(std::vector<T>& values, std::size_t width, const std::vector<std::uint32_t>& newIndex) {
  if (values.size() != width * newIndex.size()) return;
  std::size_t out = 0;
  for (std::size_t v = 0; v < newIndex.size(); ++v) {
    if (newIndex[v] == kNoVertex) continue;
    for (std::size_t j = 0; j < width; ++j) values[out++] = values[width * v + j];
  }
  values.resize(out);
}

}  // namespace

void jettisonUnused(Mesh& mesh, const std::vector<std::uint32_t>& mergedInto, std::size_t keepBelow) {
  const std::size_t n = mesh.points.size() / 2;
  std::vector<std::uint32_t> newIndex(n, kNoVertex);
  std::uint32_t kept = 0;
  for (std::size_t v = 0; v < n; ++v)
    if (v < keepBelow || static_cast<VertexKind>(mesh.vertexKinds[v]) != VertexKind::Unused) newIndex[v] = kept++;
  if (kept == n) return;
  if (!mergedInto.empty()) mesh.inputToOutput.resize(mergedInto.size());
  for (std::size_t i = 0; i < mergedInto.size(); ++i) {
    const std::uint32_t o = newIndex[mergedInto[i]];
    mesh.inputToOutput[i] = o == kNoVertex ? -1 : static_cast<std::int32_t>(o);
  }
  // No triangle, subsegment or edge uses an Unused point, so these renumber without a gap.
  for (std::uint32_t& v : mesh.triangles) v = newIndex[v];
  for (std::uint32_t& v : mesh.segments) v = newIndex[v];
  for (std::uint32_t& v : mesh.edges) v = newIndex[v];
  auto renumber = [&](std::uint32_t& v) { v = v < n ? newIndex[v] : kNoVertex; };
  for (Event& e : mesh.events) {
    renumber(e.vertex), renumber(e.a), renumber(e.b), renumber(e.t0), renumber(e.t1), renumber(e.t2);
    if (e.by >= 0) e.by = std::size_t(e.by) < n && newIndex[e.by] != kNoVertex ? std::int64_t(newIndex[e.by]) : -1;
  }
  compact(mesh.points, 2, newIndex);
  compact(mesh.vertexKinds, 1, newIndex);
  compact(mesh.pointMarkers, 1, newIndex);
  compact(mesh.pointAttributes, mesh.attributesPerPoint, newIndex);
}

}  // namespace ruppert::detail
RUPPERT_COLD_END
