// Step 3 of the OGC layout (ogc_layout.h): the polygons with holes that a plane graph bounds.
//
// Every edge of the graph (node_rounding.h) has the region on exactly one side, and around a
// vertex the sectors between its edges alternate in and out. One sweep over the vertices from left
// to right, keeping the edges it crosses in their vertical order, finds for each connected part of
// the graph the edge just below its leftmost vertex: whether the region lies there (so which side
// of every edge of the part is inside), and in which face the part lies. Walking each face of the
// region with the region on the left, turning as sharply right as the graph allows, gives its
// boundary; a walk that comes back to a vertex is cut there into simple rings (shells touching
// themselves at a point become a shell and a hole, as OGC wants). Counter-clockwise rings are
// shells, clockwise ones holes; a part's outer walk inside a face of the region holds holes of
// that face's shell. All decided with exact orientations of the doubles.
// O(E log E) for E edges.
#pragma once

#include <vector>

#include "ghclip/polygons_with_holes.h"
#include "layout/node_rounding.h"
#include "predicates/exact_counters.h"

namespace gh::detail {

std::vector<PolygonWithHoles> planeFaces(const PlaneGraph& graph, ExactCounters& counters);

}  // namespace gh::detail
