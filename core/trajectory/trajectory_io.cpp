#include "core/trajectory/trajectory_io.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>
#include <string_view>

#include <Eigen/LU>
#include <spdlog/spdlog.h>
#include <Eigen/SVD>

#include "core/util/atomic_write.hpp"
#include "core/util/error.hpp"

namespace facadeslam {
namespace {

constexpr std::string_view kTumExpectation = "expected 8 numbers (timestamp tx ty tz qx qy qz qw)";
constexpr std::string_view kKittiExpectation = "expected 12 numbers (row-major 3x4 pose [R | t])";
constexpr std::string_view kTimesExpectation = "expected 1 number (a timestamp in seconds)";

// One non-blank, non-comment line split into whitespace-separated words.
struct WordLine {
  std::size_t line_number = 0;  // 1-based, as an editor shows it
  std::vector<std::string> words;
};

[[noreturn]] void fail_line(const std::filesystem::path& path, std::size_t line, const std::string& what) {
  throw Error(path.string() + ":" + std::to_string(line) + ": " + what);
}

std::vector<WordLine> read_word_lines(const std::filesystem::path& path, const std::string& what) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) fail_file(path, "no such file (expected " + what + ")");
  if (!std::filesystem::is_regular_file(path, ec)) fail_file(path, "not a regular file (expected " + what + ")");
  std::ifstream in(path);
  if (!in) fail_file(path, "cannot open for reading (expected " + what + ")");

  std::vector<WordLine> lines;
  std::string text;
  for (std::size_t number = 1; std::getline(in, text); ++number) {
    // Everything after '#' is a comment (TUM files start with a few of them).
    if (const auto hash = text.find('#'); hash != std::string::npos) text.erase(hash);
    WordLine line{number, {}};
    std::size_t pos = 0;
    const auto is_space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; };
    while (pos < text.size()) {
      while (pos < text.size() && is_space(text[pos])) ++pos;
      const std::size_t start = pos;
      while (pos < text.size() && !is_space(text[pos])) ++pos;
      if (pos > start) line.words.emplace_back(text.substr(start, pos - start));
    }
    if (!line.words.empty()) lines.push_back(std::move(line));
  }
  if (in.bad()) fail_file(path, "read error");
  return lines;
}

std::optional<double> parse_finite(std::string_view word) {
  if (!word.empty() && word.front() == '+') word.remove_prefix(1);  // from_chars rejects '+'
  double value = 0.0;
  const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), value);
  if (ec != std::errc() || end != word.data() + word.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

std::vector<double> parse_numbers(const std::filesystem::path& path, const WordLine& line, std::size_t count,
                                  std::string_view expectation) {
  if (line.words.size() != count)
    fail_line(path, line.line_number, std::string(expectation) + ", got " + std::to_string(line.words.size()));
  std::vector<double> values;
  values.reserve(count);
  for (const auto& word : line.words) {
    const auto value = parse_finite(word);
    if (!value) fail_line(path, line.line_number, std::string(expectation) + "; '" + word + "' is not a finite number");
    values.push_back(*value);
  }
  return values;
}

// Time must not go backwards. Equal neighbours are allowed: the TUM ground
// truth rounds to 0.1 ms and so repeats a timestamp now and then (fr2_desk
// line 10863); association then simply prefers the first of the two.
void require_non_decreasing(const std::filesystem::path& path, std::size_t line_number, double previous,
                            double current) {
  if (current >= previous) return;
  char buf[160];
  std::snprintf(buf, sizeof buf, "timestamp %.9f is smaller than the previous one (%.9f); expected time order", current,
                previous);
  fail_line(path, line_number, buf);
}

StampedPose tum_pose(const std::filesystem::path& path, const WordLine& line) {
  const auto v = parse_numbers(path, line, 8, kTumExpectation);
  Eigen::Quaterniond q(v[7], v[4], v[5], v[6]);  // Eigen's order is (w, x, y, z)
  const double norm = q.norm();
  if (!(norm > 1e-9)) fail_line(path, line.line_number, "quaternion (qx qy qz qw) has zero length");
  q.coeffs() /= norm;
  StampedPose pose;
  pose.timestamp = v[0];
  pose.T_w_c.linear() = q.toRotationMatrix();
  pose.T_w_c.translation() = Eigen::Vector3d(v[1], v[2], v[3]);
  return pose;
}

// KITTI files print rotations with ~7 digits, so the block is only nearly
// orthonormal; it is snapped to the closest rotation. Anything far from a
// rotation is a wrong file rather than rounding.
Eigen::Isometry3d kitti_pose(const std::filesystem::path& path, const WordLine& line) {
  const auto v = parse_numbers(path, line, 12, kKittiExpectation);
  Eigen::Matrix3d R;
  Eigen::Vector3d t;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) R(r, c) = v[static_cast<std::size_t>(4 * r + c)];
    t(r) = v[static_cast<std::size_t>(4 * r + 3)];
  }
  const double orthogonality_error = (R.transpose() * R - Eigen::Matrix3d::Identity()).norm();
  if (orthogonality_error > 1e-2 || R.determinant() <= 0.0)
    fail_line(path, line.line_number, "the left 3x3 block is not a rotation matrix");
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(R, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = svd.matrixU() * svd.matrixV().transpose();
  T.translation() = t;
  return T;
}

Trajectory read_tum(const std::filesystem::path& path, const std::vector<WordLine>& lines) {
  Trajectory trajectory;
  trajectory.reserve(lines.size());
  std::size_t duplicates = 0;
  for (const auto& line : lines) {
    auto pose = tum_pose(path, line);
    if (!trajectory.empty()) {
      require_non_decreasing(path, line.line_number, trajectory.back().timestamp, pose.timestamp);
      // A line repeated word for word would count its pose twice in every
      // figure: kept once.
      if (pose.timestamp == trajectory.back().timestamp && pose.T_w_c.isApprox(trajectory.back().T_w_c, 0.0)) {
        ++duplicates;
        continue;
      }
    }
    trajectory.push_back(pose);
  }
  if (trajectory.size() >= 2 && trajectory.front().timestamp == trajectory.back().timestamp)
    fail_file(path, "all " + std::to_string(trajectory.size()) +
                        " timestamps are equal (expected timestamps that advance, in seconds)");
  if (duplicates) spdlog::warn("{}: {} repeated line(s) read once", path.string(), duplicates);
  return trajectory;
}

std::vector<double> read_times(const std::filesystem::path& times_path, std::size_t pose_count,
                               const std::filesystem::path& trajectory_path) {
  const auto lines = read_word_lines(times_path, "a times file, one timestamp per line");
  if (lines.size() != pose_count)
    fail_file(times_path, "has " + std::to_string(lines.size()) + " timestamps but " + trajectory_path.string() +
                              " has " + std::to_string(pose_count) + " poses (expected one timestamp per pose)");
  std::vector<double> times;
  times.reserve(lines.size());
  for (const auto& line : lines) {
    const double t = parse_numbers(times_path, line, 1, kTimesExpectation)[0];
    if (!times.empty()) require_non_decreasing(times_path, line.line_number, times.back(), t);
    times.push_back(t);
  }
  return times;
}

Trajectory read_kitti(const std::filesystem::path& path, const std::vector<WordLine>& lines,
                      const std::filesystem::path& times_path, double rate_hz) {
  const double frame_interval = rate_hz > 0.0 ? 1.0 / rate_hz : 1.0;
  Trajectory trajectory;
  trajectory.reserve(lines.size());
  for (std::size_t i = 0; i < lines.size(); ++i)
    trajectory.push_back({static_cast<double>(i) * frame_interval, kitti_pose(path, lines[i])});
  if (!times_path.empty()) {
    const auto times = read_times(times_path, trajectory.size(), path);
    for (std::size_t i = 0; i < trajectory.size(); ++i) trajectory[i].timestamp = times[i];
  }
  return trajectory;
}

std::vector<WordLine> read_pose_lines(const std::filesystem::path& path) {
  auto lines = read_word_lines(path, "a TUM or KITTI trajectory file");
  if (lines.empty()) fail_file(path, "no poses (expected a TUM or KITTI trajectory file)");
  return lines;
}

// By the first pose line; a later line with another column count is an
// error of that line (parse_numbers).
TrajectoryFormat format_of(const std::filesystem::path& path, const std::vector<WordLine>& lines) {
  const auto columns = lines.front().words.size();
  if (columns == 8) return TrajectoryFormat::tum;
  if (columns == 12) return TrajectoryFormat::kitti;
  fail_line(path, lines.front().line_number,
            "cannot tell the trajectory format: expected 8 numbers per line (TUM) or 12 (KITTI), got " +
                std::to_string(columns));
}

}  // namespace

TrajectoryFormat parse_trajectory_format(const std::string& name) {
  if (name == "auto") return TrajectoryFormat::auto_detect;
  if (name == "tum") return TrajectoryFormat::tum;
  if (name == "kitti") return TrajectoryFormat::kitti;
  throw Error("trajectory format: expected 'auto', 'tum' or 'kitti', got '" + name + "'");
}

std::string to_string(TrajectoryFormat format) {
  switch (format) {
    case TrajectoryFormat::auto_detect: return "auto";
    case TrajectoryFormat::tum: return "tum";
    case TrajectoryFormat::kitti: return "kitti";
  }
  return "?";
}

Trajectory read_trajectory(const std::filesystem::path& path, TrajectoryFormat format,
                           const std::filesystem::path& times_path, double rate_hz) {
  if (!std::isfinite(rate_hz) || rate_hz < 0.0)
    throw Error("frame rate of " + path.string() + ": expected a positive number of frames per second, got " +
                std::to_string(rate_hz));
  const auto lines = read_pose_lines(path);
  if (format == TrajectoryFormat::auto_detect) format = format_of(path, lines);
  if (format == TrajectoryFormat::tum) {
    if (!times_path.empty())
      fail_file(times_path, "a times file applies only to KITTI trajectories, and " + path.string() +
                                " is in TUM format (its timestamps are in the first column)");
    return read_tum(path, lines);
  }
  return read_kitti(path, lines, times_path, rate_hz);
}

TrajectoryFormat detect_trajectory_format(const std::filesystem::path& path) {
  return format_of(path, read_pose_lines(path));
}

void write_tum_trajectory(const std::filesystem::path& path, const Trajectory& trajectory) {
  write_atomically(path, [&](std::ostream& out) {
    out << "# timestamp tx ty tz qx qy qz qw\n";
    char buf[256];
    for (const auto& pose : trajectory) {
      const Eigen::Vector3d t = pose.T_w_c.translation();
      const Eigen::Quaterniond q(pose.T_w_c.linear());
      std::snprintf(buf, sizeof buf, "%.9f %.15g %.15g %.15g %.15g %.15g %.15g %.15g\n", pose.timestamp, t.x(), t.y(),
                    t.z(), q.x(), q.y(), q.z(), q.w());
      out << buf;
    }
  });
}

}  // namespace facadeslam
