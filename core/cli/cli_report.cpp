// Human-readable reports for the `ruppert` executable.
#include "cli_report.h"

#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>

#include "io/text_out.h"

namespace ruppert::cli {
namespace {

using detail::TextOut;

std::string fixed(double v, int decimals) {
  if (!std::isfinite(v)) return "-";  // never print "nan"
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

std::string real(double v) {
  if (!std::isfinite(v)) return "null";
  return detail::realText(v);
}

const char* reasonLabel(ReasonKind kind) {
  switch (kind) {
    case ReasonKind::SmallInputAngle: return "small input angle";
    case ReasonKind::SeditiousEdge: return "seditious edge";
    case ReasonKind::SteinerBudget: return "Steiner budget reached";
    case ReasonKind::PrecisionFloor: return "precision floor";
    case ReasonKind::Cancelled: return "cancelled";
    case ReasonKind::AngleUnreachable: return "angle out of reach";
    case ReasonKind::SegmentSplitForbidden: return "segment split forbidden";
  }
  return "unknown";
}

// The --trace file's kind: the event's name (kEventKindNames) in camelCase, "SEGMENT_SPLIT" -> "segmentSplit".
std::string eventName(EventKind kind) {
  std::string out;
  bool upper = false;
  for (const char* c = enumName(kind); *c != '\0'; ++c) {
    if (*c == '_') {
      upper = true;
      continue;
    }
    out += upper ? *c : static_cast<char>(*c - 'A' + 'a');
    upper = false;
  }
  return out;
}

void summaryTo(TextOut& out, const Mesh& mesh) {
  const Stats& s = mesh.stats;
  out << "ruppert: " << s.vertices << " vertices, " << mesh.triangles.size() / 3 << " triangles, min angle "
      << fixed(s.minAngle, 2) << ", max angle " << fixed(s.maxAngle, 1) << ", "
      << (mesh.complete ? "complete" : "incomplete") << ", " << fixed(s.milliseconds, 1) << " ms\n";
  if (mesh.complete) return;
  out << "incomplete: ";
  if (mesh.reasons.empty()) out << "no reason given";
  for (std::size_t i = 0; i < mesh.reasons.size(); ++i) {
    const Reason& r = mesh.reasons[i];
    out << (i ? "; " : "");
    if (!r.message.empty()) out << r.message;
    else out << reasonLabel(r.kind) << " (" << r.count << ")";
  }
  out << '\n';
}

void statsTo(TextOut& out, const Stats& s) {
  out << "vertices: " << s.vertices << " (input " << s.inputVertices << ", on segments " << s.segmentVertices
      << ", circumcenters " << s.interiorVertices << ", off-centers " << s.offCenterVertices << ", intersections "
      << s.intersectionVertices << ")\n";
  out << "triangles: " << s.triangles << '\n';
  out << "angles: min " << fixed(s.minAngle, 4) << ", max " << fixed(s.maxAngle, 4) << " degrees (min "
      << fixed(s.reachedAngle, 4) << " without the section 6.6 exemptions)\n";
  // 180 one-degree bins are too many for a terminal; ten-degree groups show the shape.
  out << "angle histogram (degrees: count):";
  bool any = false;
  for (std::size_t g = 0; g * 10 < s.angleHistogram.size(); ++g) {
    std::uint64_t sum = 0;
    for (std::size_t b = g * 10; b < (g + 1) * 10 && b < s.angleHistogram.size(); ++b) sum += s.angleHistogram[b];
    if (sum == 0) continue;
    out << ' ' << g * 10 << '-' << g * 10 + 10 << ':' << sum;
    any = true;
  }
  out << (any ? "\n" : " (empty)\n");
  out << "rejected circumcenters: " << s.rejectedCircumcenters << '\n';
  out << "lfs integral: " << fixed(s.lfsIntegral, 3) << ", triangles per unit of it: "
      << fixed(s.trianglesPerLfsIntegral, 3) << '\n';
  out << "time: " << fixed(s.milliseconds, 3) << " ms\n";
}

void traceTo(TextOut& out, const Mesh& mesh) {
  for (const Event& e : mesh.events) {
    out << "{\"kind\":\"" << eventName(e.kind) << "\",\"vertex\":" << e.vertex << ",\"x\":" << real(e.x)
        << ",\"y\":" << real(e.y);
    if (e.kind == EventKind::SegmentSplit || e.kind == EventKind::Rejected) {
      out << ",\"a\":" << e.a << ",\"b\":" << e.b;
    }
    if (e.kind == EventKind::SegmentSplit) out << ",\"by\":" << e.by;
    if (e.kind != EventKind::SegmentSplit) {
      out << ",\"triangle\":[" << e.t0 << ',' << e.t1 << ',' << e.t2 << ']';
    }
    if (e.kind == EventKind::Rejected) out << ",\"cx\":" << real(e.cx) << ",\"cy\":" << real(e.cy);
    if (e.kind == EventKind::Relocated) out << ",\"from\":[" << real(e.cx) << ',' << real(e.cy) << ']';
    out << "}\n";
  }
}

}  // namespace

std::string summaryText(const Mesh& mesh) {
  TextOut out;
  summaryTo(out, mesh);
  return out.take();
}

std::string statsText(const Stats& stats) {
  TextOut out;
  statsTo(out, stats);
  return out.take();
}

std::string traceText(const Mesh& mesh) {
  TextOut out;
  traceTo(out, mesh);
  return out.take();
}

void writeTrace(std::ostream& stream, const Mesh& mesh) {
  TextOut out(detail::writeToStream<std::ostream>, &stream);
  traceTo(out, mesh);
  out.flush();
}

}  // namespace ruppert::cli
