#include "core/camera/camera_yaml.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>
#include <type_traits>
#include <vector>

#include <Eigen/LU>

#include "core/config/config_node.hpp"
#include "core/util/atomic_write.hpp"

namespace facadeslam {
namespace {

std::string exact(double v) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  return buffer;
}

std::string pixel_text(const Eigen::Vector2d& px) {
  std::ostringstream s;
  s << "(" << px(0) << ", " << px(1) << ")";
  return s.str();
}

// Every pixel must have a ray: the ATAN model is only defined up to 90
// degrees, reached at distorted radius pi / (2 w); its largest radius in
// the image is at a corner of the pixel area.
void check_atan_covers_image(const ConfigNode& node, const Camera& camera, const AtanCamera& atan_model) {
  const double x_edges[] = {-0.5, camera.width() - 0.5};
  const double y_edges[] = {-0.5, camera.height() - 0.5};
  for (double x : x_edges)
    for (double y : y_edges) {
      const Eigen::Vector2d xd((x - atan_model.cx) / atan_model.fx, (y - atan_model.cy) / atan_model.fy);
      if (xd.norm() >= atan_model.max_distorted_radius())
        node.fail("w",
                  "a value small enough that every image corner lies inside the model's 90-degree field "
                  "(corner " +
                      pixel_text({x, y}) + " does not)",
                  exact(atan_model.w));
    }
}

// Radial-tangential polynomials fold back beyond some radius; a calibration
// whose fold lies inside the image leaves pixels with no ray, or two. Check a
// grid over the whole image (edges included) for a converged, locally
// one-to-one undistortion.
void check_pinhole_covers_image(const ConfigNode& node, const Camera& camera, const PinholeRadTan& pinhole) {
  if (!pinhole.has_distortion()) return;
  constexpr int kSteps = 32;
  for (int j = 0; j <= kSteps; ++j)
    for (int i = 0; i <= kSteps; ++i) {
      const Eigen::Vector2d px((camera.width() - 1) * i / double(kSteps), (camera.height() - 1) * j / double(kSteps));
      const Eigen::Vector3d ray = pinhole.unproject(px);
      const bool round_trip = (pinhole.project(ray) - px).norm() < 1e-6;
      const bool one_to_one = pinhole.distort_jacobian(ray.head<2>()).determinant() > 0.0;
      if (!round_trip || !one_to_one)
        node.fail("distortion", "coefficients that can be inverted over the whole image (at pixel " + pixel_text(px) +
                                    " the distortion polynomial has folded back)");
    }
}

}  // namespace

Camera load_camera(const std::filesystem::path& path) {
  const ConfigNode node = ConfigNode::load_file(path);
  const std::string model = node.get_choice("model", {"pinhole", "atan"});
  const int width = node.get_int("width", Range::closed(16, 20000));
  const int height = node.get_int("height", Range::closed(16, 20000));
  // Focal lengths in pixels for fields of view between ~170 and ~0.1
  // degrees: 0.001 or 1e12 is a typo (or PTAM's image-normalised values).
  const double fx = node.get_double("fx", Range::closed(0.05 * width, 500.0 * width));
  const double fy = node.get_double("fy", Range::closed(0.05 * height, 500.0 * height));
  const double cx = node.get_double("cx", Range::closed(-width, 2.0 * width));
  const double cy = node.get_double("cy", Range::closed(-height, 2.0 * height));

  if (model == "pinhole") {
    PinholeRadTan pinhole{.fx = fx, .fy = fy, .cx = cx, .cy = cy};
    if (node.has("distortion")) {
      const std::vector<double> d = node.get_doubles("distortion", 5);
      pinhole.k1 = d[0];
      pinhole.k2 = d[1];
      pinhole.p1 = d[2];
      pinhole.p2 = d[3];
      pinhole.k3 = d[4];
    }
    node.finish();
    const Camera camera(width, height, pinhole);
    check_pinhole_covers_image(node, camera, pinhole);
    return camera;
  }
  const AtanCamera atan_model{
      .fx = fx, .fy = fy, .cx = cx, .cy = cy, .w = node.get_double("w", Range{0.0, 3.0, false, true})};
  node.finish();
  const Camera camera(width, height, atan_model);
  check_atan_covers_image(node, camera, atan_model);
  return camera;
}

void save_camera(const std::filesystem::path& path, const Camera& camera, const std::string& comment_header) {
  std::ostringstream out;
  if (!comment_header.empty()) {
    std::istringstream lines(comment_header);
    for (std::string line; std::getline(lines, line);) out << (line.empty() ? "#" : "# " + line) << "\n";
  }
  out << "# facadeslam camera (format: see configs/camera/*.yaml)\n"
      << "model: " << camera.model_name() << "  # pinhole (OpenCV radial-tangential) | atan (PTAM FOV model)\n"
      << "width: " << camera.width() << "  # image size in pixels\n"
      << "height: " << camera.height() << "\n"
      << "fx: " << exact(camera.fx()) << "  # focal lengths in pixels\n"
      << "fy: " << exact(camera.fy()) << "\n"
      << "cx: " << exact(camera.cx()) << "  # principal point in pixels; (0,0) is the centre of the top-left pixel\n"
      << "cy: " << exact(camera.cy()) << "\n";
  camera.visit([&](const auto& m) {
    using M = std::decay_t<decltype(m)>;
    if constexpr (std::is_same_v<M, PinholeRadTan>) {
      out << "distortion: [" << exact(m.k1) << ", " << exact(m.k2) << ", " << exact(m.p1) << ", " << exact(m.p2) << ", "
          << exact(m.k3) << "]  # OpenCV order k1, k2, p1, p2, k3\n";
    } else {
      out << "w: " << exact(m.w) << "  # FOV distortion parameter in radians (0 = none)\n";
    }
  });
  write_text_atomically(path, out.str());
}

}  // namespace facadeslam
