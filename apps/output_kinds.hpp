#pragma once
// The files and folders the facadeslam commands write, as the output policy
// (core/util/output_policy.hpp) recognises them on disk: a command replaces
// only these, and an output folder only when everything in it is one of them.
// Recognised by content, never by name alone: a user's notes saved as
// report.json are not a replay report.
#include <memory>

#include "core/util/output_policy.hpp"

namespace facadeslam::apps {

OutputFileKind png_picture_kind();            // any PNG this program draws
OutputFileKind map_file_kind();               // replay --save-map (.fslmap magic)
OutputFileKind model_file_kind();             // train --out (.fsmodel magic)
OutputFileKind model_out_kind();              // evaluate labels --model-out: .fsmodel or OpenCV's .yml.gz
OutputFileKind calibrated_camera_kind();      // calibrate --out: a camera YAML calibrate wrote
OutputFileKind calibration_report_kind();     // calibrate --json
OutputFileKind trajectory_evaluation_kind();  // evaluate trajectory --json
OutputFileKind label_evaluation_kind();       // evaluate labels --json
OutputFileKind invariance_report_kind();      // evaluate invariance --json
OutputFileKind training_summary_kind();       // train's NAME.fsmodel.json

// replay --out: report.json, trajectories, map.ply and its class table, maps,
// trajectory.png and render folders.
std::shared_ptr<const OutputFolderLayout> replay_folder_layout();
// replay --render DIR: frames/ar_NNNNNN.png, augmented.mp4, contact_sheet.png.
std::shared_ptr<const OutputFolderLayout> render_folder_layout();
// synth --out: rgb/, label/, depth/, the lists, camera.yaml, labels.txt,
// scene.yaml, synth.json (and a contact sheet put there).
std::shared_ptr<const OutputFolderLayout> synth_folder_layout();
// optimise --out: split.json, generation-NNN.json, best.*, fitness.*.
std::shared_ptr<const OutputFolderLayout> optimise_folder_layout();

}  // namespace facadeslam::apps
