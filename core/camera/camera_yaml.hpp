#pragma once
// Camera YAML files (configs/camera/*.yaml):
//
//   model: pinhole        # pinhole (OpenCV radial-tangential) | atan (PTAM FOV model)
//   width: 640            # image size in pixels, integers in [16, 20000]
//   height: 480
//   fx: 535.9             # focal lengths in pixels, > 0
//   fy: 535.9
//   cx: 342.3             # principal point in pixels, cx in [-width, 2 width],
//   cy: 235.6             #   cy in [-height, 2 height]; (0,0) = centre of the top-left pixel
//   distortion: [k1, k2, p1, p2, k3]   # pinhole only; optional (absent = zeros)
//   w: 0.92               # atan only: FOV parameter in radians, [0, 3)
//
// A `distortion` key on an atan camera or `w` on a pinhole camera is an
// unknown key. Beyond per-key checks, the model must be invertible over the
// whole image (every pixel has a ray): an ATAN w so large that the corners lie
// beyond 90 degrees, or pinhole coefficients whose polynomial folds back
// inside the image, are rejected naming the key.
#include <filesystem>
#include <string>

#include "core/camera/camera.hpp"

namespace facadeslam {

// Throws Error naming the file, the key and the expectation on any problem.
Camera load_camera(const std::filesystem::path& path);

// Writes atomically, every number with 17 significant digits so that
// load_camera() reads back exactly the same camera. `comment_header`
// (may span lines) is written as '#' comments at the top.
void save_camera(const std::filesystem::path& path, const Camera& camera, const std::string& comment_header = {});

}  // namespace facadeslam
