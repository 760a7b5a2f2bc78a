#include "apps/output_kinds.hpp"

#include <fstream>
#include <string>
#include <utility>

namespace facadeslam::apps {
namespace {

namespace fs = std::filesystem;

OutputFileKind fsmodel_kind() { return file_starting_with("a forest model (.fsmodel)", std::string("FSMODEL\0", 8)); }

// ISO base media (MP4): a box whose type, at byte 4, is "ftyp".
OutputFileKind mp4_kind() {
  return {"an MP4 video", [](const fs::path& path) {
            std::ifstream in(path, std::ios::binary);
            char head[8] = {};
            return in.read(head, sizeof head) && std::string(head + 4, 4) == "ftyp";
          }};
}

OutputFileKind tum_trajectory_kind() { return numbered_lines("a TUM trajectory"); }

OutputFileKind optimise_json_kind() { return json_object_with_keys("an optimise result (JSON)", {}); }

std::shared_ptr<const OutputFolderLayout> pictures_layout(std::string description) {
  return std::make_shared<const OutputFolderLayout>(
      OutputFolderLayout{std::move(description), {file_entry("*.png", png_picture_kind())}});
}

}  // namespace

OutputFileKind png_picture_kind() { return png_file("a PNG picture drawn by facadeslam"); }

OutputFileKind map_file_kind() { return file_starting_with("a facadeslam map (.fslmap)", "FSLAMMAP"); }

OutputFileKind model_file_kind() { return fsmodel_kind(); }

OutputFileKind model_out_kind() {
  return any_of("a forest model (.fsmodel, or OpenCV's .yml.gz)",
                {fsmodel_kind(), file_starting_with("gzip", std::string("\x1f\x8b", 2))});
}

OutputFileKind calibrated_camera_kind() {
  return text_with_line("a camera YAML written by facadeslam calibrate", "# Calibrated by `facadeslam calibrate`");
}

OutputFileKind calibration_report_kind() {
  return json_object_with_keys("a calibrate report (JSON)", {"images", "board", "rms_px", "camera"});
}

OutputFileKind trajectory_evaluation_kind() {
  return json_object_with_keys("an evaluate trajectory report (JSON)", {"ate_rmse_m", "rpe_trans_rmse_m", "alignment"});
}

OutputFileKind label_evaluation_kind() {
  return any_of("an evaluate labels report (JSON)",
                {json_object_with_keys("one descriptor's", {"dataset", "descriptor", "genome", "grid_step"}),
                 json_object_with_keys("a comparison", {"comparison", "runs"})});
}

OutputFileKind invariance_report_kind() {
  return json_object_with_keys("an evaluate invariance report (JSON)",
                               {"images", "grid_step", "margin", "reference_keypoints"});
}

OutputFileKind training_summary_kind() {
  return json_object_with_keys("a train summary (MODEL.fsmodel.json)",
                               {"model", "model_bytes", "format_version", "dataset", "split"});
}

std::shared_ptr<const OutputFolderLayout> render_folder_layout() {
  static const auto layout = std::make_shared<const OutputFolderLayout>(OutputFolderLayout{
      "an earlier replay --render folder",
      {folder_entry("frames", pictures_layout("replay --render's frames")), file_entry("augmented.mp4", mp4_kind()),
       file_entry("contact_sheet.png", png_picture_kind())}});
  return layout;
}

// segments/N/ after map resets: each map's trajectories (replay_outputs.cpp).
std::shared_ptr<const OutputFolderLayout> trajectory_segments_layout() {
  static const auto segment = std::make_shared<const OutputFolderLayout>(
      OutputFolderLayout{"a replay's trajectory segment",
                         {file_entry("trajectory.txt", tum_trajectory_kind()),
                          file_entry("trajectory_online.txt", tum_trajectory_kind())}});
  static const auto layout = std::make_shared<const OutputFolderLayout>(
      OutputFolderLayout{"a replay's trajectory segments", {folder_entry("*", segment)}});
  return layout;
}

std::shared_ptr<const OutputFolderLayout> replay_folder_layout() {
  static const auto layout = std::make_shared<const OutputFolderLayout>(OutputFolderLayout{
      "an earlier replay output",
      {
          file_entry("report.json",
                     json_object_with_keys("a replay report", {"sequence", "camera", "mode", "frames", "initialised"})),
          file_entry("trajectory.txt", tum_trajectory_kind()),
          file_entry("trajectory_online.txt", tum_trajectory_kind()),
          file_entry("keyframes.txt", tum_trajectory_kind()),
          file_entry("map.ply",
                     text_with_line("a labelled point cloud (map.ply)", "comment facadeslam labelled map points")),
          file_entry("map.classes.json", json_object_with_keys("map.ply's class table", {"point_cloud", "classes"})),
          file_entry("trajectory.png", png_picture_kind()),
          // The map under the default name or the one --save-map gives it.
          file_entry("*.fslmap", map_file_kind(), /*every_run=*/false),
          // After map resets: every map's poses.
          folder_entry("segments", trajectory_segments_layout(), /*every_run=*/false),
          // --render DIR inside --out, under any name.
          folder_entry("*", render_folder_layout(), /*every_run=*/false),
      }});
  return layout;
}

std::shared_ptr<const OutputFolderLayout> synth_folder_layout() {
  static const auto layout = std::make_shared<const OutputFolderLayout>(OutputFolderLayout{
      "an earlier synth output",
      {
          folder_entry("rgb", pictures_layout("synth's colour frames")),
          folder_entry("label", pictures_layout("synth's label frames")),
          folder_entry("depth", pictures_layout("synth's depth frames")),
          file_entry("rgb.txt", numbered_lines("a TUM image list")),
          file_entry("depth.txt", numbered_lines("a TUM image list")),
          file_entry("groundtruth.txt", tum_trajectory_kind()),
          file_entry("camera.yaml", text_with_line("a camera YAML written by facadeslam", "# facadeslam camera")),
          file_entry("labels.txt", text_with_line("synth's class table", "# facadeslam synthetic sequence")),
          file_entry("scene.yaml", text_file("a copy of the scene file")),
          file_entry("synth.json",
                     json_object_with_keys("a synth manifest", {"generator", "scene", "frames", "renderer"})),
          // --contact-sheet inside --out.
          file_entry("*.png", png_picture_kind(), /*every_run=*/false),
      }});
  return layout;
}

std::shared_ptr<const OutputFolderLayout> optimise_folder_layout() {
  static const auto layout = std::make_shared<const OutputFolderLayout>(
      OutputFolderLayout{"an earlier optimise run folder",
                         {
                             file_entry("split.json", optimise_json_kind()),
                             file_entry("generation-*.json", optimise_json_kind()),
                             file_entry("best.json", optimise_json_kind()),
                             file_entry("fitness.json", optimise_json_kind()),
                             file_entry("best.genome", text_file("a genome")),
                             file_entry("fitness.png", png_picture_kind()),
                             file_entry("best.fsmodel", fsmodel_kind()),
                         }});
  return layout;
}

}  // namespace facadeslam::apps
