#pragma once
// Labels from the map's neighbourhoods. A point's own votes come from the
// few keyframes that saw it, each a 21-pixel patch; its neighbours in 3D lie
// on the same wall, the same tree, the same road, and a patch that looks like
// a tree on a wall is outvoted by the wall around it. Each labelled point's
// label becomes the arg-max of its own vote shares and those of its
// `neighbours` nearest labelled points (Euclidean, in the map's frame; every
// point's shares count once, however many views it has), the confidence the
// winner's share of that sum. The points' votes are not changed: the map file
// keeps each point's own evidence and the fusion is run again on loading.
//
// street-walk (--sync): label accuracy 0.674 with the points' own votes, 0.707
// with 10 neighbours, 0.714 with 15 (building 0.88 -> 0.95, vegetation 0.68 ->
// 0.72, road 0.99 -> 0.97), 0.717 with 20 (road 0.93); docs/benchmarks.md.
#include <cstddef>

#include "core/map/map.hpp"

namespace facadeslam::semantics {

struct MapLabelOptions {
  // Nearest labelled map points whose vote shares join each point's own
  // (0: each point's own votes).
  int neighbours = 15;
  // Sky lies at infinity: a point that two keyframes measure at a finite
  // depth (its rays meet, as the epipolar search and the initialisation
  // require; under kFarDepthRatio x its source keyframe's mean depth) is not
  // sky, so its sky votes are left out of its label. A point only its source
  // measures (a depth-prior point, placed at its neighbours' depth) and a
  // point bundle adjustment pushed far off keep them.
  bool sky_only_at_infinity = true;
};

// A point this many times its source keyframe's mean scene depth away counts
// as at infinity.
inline constexpr double kFarDepthRatio = 20.0;

// Relabels the map's good, labelled points (under the map's shared lock for
// the positions and measurements; labels are atomics). Returns how many
// points it labelled. Deterministic: ties in distance go to the lower point id.
std::size_t fuse_labels_with_neighbours(const Map& map, const MapLabelOptions& options);

}  // namespace facadeslam::semantics
