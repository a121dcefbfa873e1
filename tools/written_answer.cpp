#include "written_answer.h"

#include <chrono>

#include "tool_main.h"

namespace gh::tools {
namespace {

void format(WrittenAnswer& w, const Region& subject, const Region& clip, Op op, io::Format format, io::Layout layout) {
  const auto start = std::chrono::steady_clock::now();
  if (layout == io::Layout::Rings) {
    w.text = io::write(w.rings, format);
  } else {
    w.text = io::write(w.polygons, format);
    if (w.layout.snapRounded) requireWithinRounding(subject, clip, op, w.text);
    w.rings = toRegion(w.polygons);
  }
  w.formatSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

WrittenAnswer writtenAnswer(Clipping& clipping, const Region& subject, const Region& clip, Op op, io::Format format,
                            io::Layout layout) {
  WrittenAnswer w;
  if (layout == io::Layout::Ogc) {
    w.polygons = clipping.polygons(op, &w.stats, &w.layout);
  } else {
    w.rings = clipping.result(op, &w.stats);
  }
  tools::format(w, subject, clip, op, format, layout);
  return w;
}

WrittenAnswer writtenAnswer(Region rings, const Region& subject, const Region& clip, Op op, io::Format format,
                            io::Layout layout) {
  WrittenAnswer w;
  if (layout == io::Layout::Ogc) {
    w.polygons = ogcLayout(rings, &w.layout);
  } else {
    w.rings = std::move(rings);
  }
  tools::format(w, subject, clip, op, format, layout);
  return w;
}

}  // namespace gh::tools
