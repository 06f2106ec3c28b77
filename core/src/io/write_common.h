// What the writers of solver and GIS formats (write_msh.cpp, write_vtu.cpp, write_geojson.cpp)
// share: the refusal of non-finite coordinates, a triangle's smallest angle and its attribute. Their
// numbers (realText) and stream/string plumbing (toStream, toText) are text_out.h's.
#pragma once

#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

#include "mesh/angle_stats.h"
#include "ruppert/ruppert.h"
#include "io/text_out.h"

namespace ruppert::detail {

// Throws Internal naming the first non-finite entry: no writer prints "nan".
inline void requireFiniteValues(const std::vector<double>& values, const char* what) {
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!std::isfinite(values[i])) {
      throw Error(ErrorCode::Internal, std::string("cannot write a non-finite value: ") + what + "[" +
                                           std::to_string(i) + "] = " + realText(values[i]));
    }
  }
}

// Every triangle index must name a point: the writers index mesh.points with them.
inline void requireTriangleIndices(const Mesh& mesh) {
  const std::size_t n = mesh.points.size() / 2;
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    if (mesh.triangles[i] >= n) {
      throw Error(ErrorCode::IndexOutOfRange, "triangles[" + std::to_string(i) + "] = " +
                                                  std::to_string(mesh.triangles[i]) + " but there are " +
                                                  std::to_string(n) + " points");
    }
  }
}

// Every subsegment's ends must name points (the .msh and .vtu write them as lines).
inline void requireSegmentIndices(const Mesh& mesh) {
  const std::size_t n = mesh.points.size() / 2;
  for (std::size_t i = 0; i < mesh.segments.size(); ++i) {
    if (mesh.segments[i] >= n) {
      throw Error(ErrorCode::IndexOutOfRange, "segments[" + std::to_string(i) + "] = " +
                                                  std::to_string(mesh.segments[i]) + " but there are " +
                                                  std::to_string(n) + " points");
    }
  }
}

// Smallest angle of triangle t in degrees.
inline double smallestAngleDegrees(const Mesh& mesh, std::size_t t) {
  const double* p[3];
  for (int k = 0; k < 3; ++k) p[k] = &mesh.points[2 * static_cast<std::size_t>(mesh.triangles[3 * t + k])];
  double angle[3];
  triangleAngles(p, angle);
  return std::fmin(angle[0], std::fmin(angle[1], angle[2])) * (180.0 / 3.14159265358979323846);
}

// The region attribute of triangle t (0 when the mesh carries none).
inline double triangleAttribute(const Mesh& mesh, std::size_t t) {
  return t < mesh.triangleAttributes.size() ? mesh.triangleAttributes[t] : 0.0;
}

}  // namespace ruppert::detail
