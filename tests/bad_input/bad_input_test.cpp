// Issue 20's bad-input corpus, run through the built `facadeslam` as a user
// runs it: every case gives its exit code, one line on stderr naming what
// was wrong (never a hostile file's raw bytes), and leaves the outputs as
// they were (absent, or an earlier run's folder untouched, and no hidden
// temporary file or folder anywhere in the case's folder). Issue 41's cases
// (a careless command line must never destroy a user's files) run beside a
// folder of the user's own files and a sequence of the user's, and every
// file in the case's folder and in the shared inputs must be as it was
// (except the one output a case may write).
//
// The raw files are in tests/bad_input/<parser>/ (README.md there); what
// would be large (frames, a dataset, a flipped byte in the shipped model)
// is made here, in one shared folder per test program run.
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <sys/stat.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "sequences/synth/label_classes.hpp"
#include "tests/apps/cli_run.hpp"
#include "tests/semantics/synthetic_facades.hpp"
#include "tests/support/smooth_texture.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

// What a failed run must leave behind in its case folder.
enum class Outputs {
  absent,     // {out} does not exist
  untouched,  // {old} (an earlier replay's output) holds exactly what it held
};

struct Case {
  const char* name;
  const char* arguments;  // with {corpus} {case} {seq} {cam} {data} {out} {old} {file} {mine} {myseq} placeholders
  int exit_code;
  const char* message;  // a substring of stderr (or, for exit 0, of stderr's warning)
  Outputs outputs = Outputs::absent;
  const char* stdout_message = "";  // a substring of stdout
  const char* writes = "";          // the one path in the case's folder a run that succeeds may write
};

// Placeholders: {corpus} this folder in the source tree, {shared} the shared
// generated inputs, {seq} a 3-frame TUM sequence (640x480), {cam} its
// camera, {data} a tiny LabelMeFacade-layout dataset, {out} an output
// folder that must stay absent, {old} an earlier replay's output folder,
// {file} a regular file, {case} the case's own folder, {mine} a folder of
// the user's own files (notes.txt, thesis.tex, a report.json and a
// synth.json that are plain text, a hand-made camera.yaml, a file named
// old.fsmodel that is no model, photos/ with two PNGs, gt.txt), {myseq} a
// copy of {seq} of the user's with a report.json in it.
const Case kCases[] = {
    // rgb.txt lists
    {"rgb_txt_garbage_bytes", "replay {corpus}/rgb_txt/garbage_bytes.txt --camera {cam} --out {out}", 1,
     "garbage_bytes.txt: line 1: '\\x01\\xff\\xfeGARBAGE\\x1b[31m' is not a timestamp"},
    {"rgb_txt_three_fields", "replay {corpus}/rgb_txt/three_fields.txt --camera {cam} --out {out}", 1,
     "three_fields.txt: line 2: found 3 fields"},
    {"rgb_txt_one_field", "replay {corpus}/rgb_txt/one_field.txt --camera {cam} --out {out}", 1,
     "one_field.txt: line 1: found 1 fields"},
    {"rgb_txt_nan_timestamp", "replay {corpus}/rgb_txt/nan_timestamp.txt --camera {cam} --out {out}", 1,
     "nan_timestamp.txt: line 1"},
    {"rgb_txt_decreasing", "replay {corpus}/rgb_txt/decreasing.txt --camera {cam} --out {out}", 1,
     "decreasing.txt: line 2"},
    {"rgb_txt_duplicate_timestamp", "replay {corpus}/rgb_txt/duplicate_timestamp.txt --camera {cam} --out {out}", 1,
     "duplicate_timestamp.txt: line 2"},
    {"rgb_txt_missing_image", "replay {corpus}/rgb_txt/missing_image.txt --camera {cam} --out {out}", 1,
     "does-not-exist.png does not exist"},
    {"rgb_txt_comments_only", "replay {corpus}/rgb_txt/comments_only.txt --camera {cam} --out {out}", 1,
     "comments_only.txt: no images found"},
    {"rgb_txt_empty", "replay {corpus}/rgb_txt/empty.txt --camera {cam} --out {out}", 1, "empty.txt: no images found"},
    // Frames (made here): zero-byte, truncated, of another size; a corrupt
    // frame skipped is counted in the summary.
    {"frames_zero_byte_stop", "replay {shared}/zero_byte --camera {cam} --on-corrupt stop --out {out}", 1,
     "000001.png"},
    {"frames_truncated_stop", "replay {shared}/truncated --camera {cam} --on-corrupt stop --out {out}", 1,
     "000001.png"},
    {"frames_mixed_size", "replay {shared}/mixed_size --camera {cam} --semantics off --out {out}", 1,
     "image is 320x240 but the sequence's first frame"},
    {"frames_mixed_size_keeps_the_old_output", "replay {shared}/mixed_size --camera {cam} --semantics off --out {old}",
     1, "image is 320x240", Outputs::untouched},
    {"frames_corrupt_skipped_are_counted",
     "replay {shared}/zero_byte --camera {cam} --semantics off --sync --out {case}/counted", 3, "never initialised",
     Outputs::absent, "1 corrupt frames skipped", "counted"},
    // --render where no object can stand (issue 44): the frames are drawn
    // without it and a line says why, through a strongly distorted camera too.
    {"render_without_a_map_says_why_through_a_strong_distortion",
     "replay {seq} --camera {corpus}/camera_yaml/strong_distortion.yaml --semantics off --sync --render {case}/run/ar "
     "--out {case}/run",
     3, "render: no virtual object in the view: no rendered frame was tracked", Outputs::absent, "rendered 3 frames",
     "run"},
    // synth.json against what the folder holds (point 2)
    {"sequence_manifest_mismatch", "replay {shared}/mixed_manifest --semantics off --out {out}", 1,
     "synth.json: says 5 frames but"},
    // camera YAML (point 5: focal bounds)
    {"camera_missing_fx", "replay {seq} --camera {corpus}/camera_yaml/missing_fx.yaml --out {out}", 1,
     "missing_fx.yaml"},
    {"camera_tiny_fx", "replay {seq} --camera {corpus}/camera_yaml/tiny_fx.yaml --out {out}", 1, "tiny_fx.yaml"},
    {"camera_huge_fx", "replay {seq} --camera {corpus}/camera_yaml/huge_fx.yaml --out {out}", 1, "huge_fx.yaml"},
    {"camera_nan_fx", "replay {seq} --camera {corpus}/camera_yaml/nan_fx.yaml --out {out}", 1, "nan_fx.yaml"},
    {"camera_negative_width", "replay {seq} --camera {corpus}/camera_yaml/negative_width.yaml --out {out}", 1,
     "negative_width.yaml"},
    {"camera_huge_size", "replay {seq} --camera {corpus}/camera_yaml/huge_size.yaml --out {out}", 1, "huge_size.yaml"},
    {"camera_unknown_model", "replay {seq} --camera {corpus}/camera_yaml/unknown_model.yaml --out {out}", 1, "fisheye"},
    {"camera_short_distortion", "replay {seq} --camera {corpus}/camera_yaml/short_distortion.yaml --out {out}", 1,
     "short_distortion.yaml"},
    {"camera_text_fx", "replay {seq} --camera {corpus}/camera_yaml/text_fx.yaml --out {out}", 1, "text_fx.yaml"},
    {"camera_unknown_key", "replay {seq} --camera {corpus}/camera_yaml/unknown_key.yaml --out {out}", 1, "fz"},
    {"camera_key_is_a_list", "replay {seq} --camera {corpus}/camera_yaml/key_is_a_list.yaml --out {out}", 1,
     "key_is_a_list.yaml: at the top level: expected keys that are plain names, got a list as a key"},
    {"camera_not_yaml", "replay {seq} --camera {corpus}/camera_yaml/not_yaml.yaml --out {out}", 1, "not_yaml.yaml"},
    {"camera_unbalanced", "replay {seq} --camera {corpus}/camera_yaml/unbalanced.yaml --out {out}", 1,
     "unbalanced.yaml"},
    {"camera_empty", "replay {seq} --camera {corpus}/camera_yaml/empty.yaml --out {out}", 1, "empty.yaml"},
    {"camera_other_size", "replay {seq} --camera {corpus}/camera_yaml/other_size_320x240.yaml --out {out}", 1,
     "image is 640x480 but the camera"},
    // SLAM and semantics config YAML
    {"slam_config_unknown_key", "replay {seq} --config {corpus}/slam_config/unknown_key.yaml --out {out}", 1,
     "fast_thresholdz"},
    {"slam_config_bad_type", "replay {seq} --config {corpus}/slam_config/bad_type.yaml --out {out}", 1,
     "bad_type.yaml"},
    {"slam_config_out_of_range", "replay {seq} --config {corpus}/slam_config/out_of_range.yaml --out {out}", 1,
     "out_of_range.yaml"},
    {"slam_config_not_a_map", "replay {seq} --config {corpus}/slam_config/not_a_map.yaml --out {out}", 1,
     "not_a_map.yaml"},
    {"slam_config_not_yaml", "replay {seq} --config {corpus}/slam_config/not_yaml.yaml --out {out}", 1,
     "not_yaml.yaml"},
    {"semantics_config_unknown_key",
     "replay {seq} --semantics-config {corpus}/semantics_config/unknown_key.yaml --out {out}", 1, "modle"},
    {"semantics_config_unknown_class",
     "replay {seq} --semantics-config {corpus}/semantics_config/unknown_class.yaml --out {out}", 1, "spaceship"},
    {"semantics_config_not_yaml", "replay {seq} --semantics-config {corpus}/semantics_config/not_yaml.yaml --out {out}",
     1, "not_yaml.yaml"},
    // Map files (hostile values with a valid checksum: tests/core/map/map_io_test.cpp)
    {"map_empty", "replay {seq} --load-map {corpus}/map/empty.fslmap --out {out}", 1, "empty.fslmap"},
    {"map_random", "replay {seq} --load-map {corpus}/map/random.fslmap --out {out}", 1, "random.fslmap"},
    {"map_bad_magic", "replay {seq} --load-map {corpus}/map/bad_magic.fslmap --out {out}", 1, "bad magic"},
    {"map_version_99", "replay {seq} --load-map {corpus}/map/version_99.fslmap --out {out}", 1, "version 99"},
    {"map_truncated_header", "replay {seq} --load-map {corpus}/map/truncated_header.fslmap --out {out}", 1,
     "truncated_header.fslmap"},
    {"map_is_a_folder", "replay {seq} --load-map {corpus}/map --out {out}", 1, "expected a map file"},
    // Model files
    {"model_empty", "replay {seq} --model {corpus}/model/empty.fsmodel --out {out}", 1, "empty.fsmodel"},
    {"model_random", "replay {seq} --model {corpus}/model/random.fsmodel --out {out}", 1,
     "not a facadeslam model file"},
    {"model_bad_magic", "replay {seq} --model {corpus}/model/bad_magic.fsmodel --out {out}", 1,
     "not a facadeslam model file"},
    {"model_version_99", "replay {seq} --model {corpus}/model/version_99.fsmodel --out {out}", 1,
     "model format version 99"},
    // A grey model where colour keyframes are labelled, and the reverse.
    {"model_grey_as_colour", "replay {seq} --model {root}/models/grey.fsmodel --out {out}", 1,
     "a model trained on grey images, given as the model, which labels colour keyframes"},
    {"model_colour_as_grey", "replay {seq} --grey-model {root}/models/default.fsmodel --out {out}", 1,
     "a model trained on colour images, given as the grey model"},
    {"semantics_street_with_a_config",
     "replay {seq} --semantics street --semantics-config {root}/configs/semantics.yaml --out {out}", 1,
     "--semantics street reads the shipped configs/semantics-street.yaml"},
    {"train_also_grey_with_grey", "train --dataset {data} --grey --also-grey --out {case}/m.fsmodel", 1,
     "--also-grey adds grey views to a colour model"},
    {"train_balance_power_without_balance", "train --dataset {data} --balance-power 0.5 --out {case}/m.fsmodel", 2,
     "--balance-power requires --balance"},
    {"model_grey_tested_colour", "evaluate labels --dataset {data} --model {root}/models/grey.fsmodel", 1,
     "a model trained on grey images, tested on colour ones (add --grey)"},
    {"model_truncated", "replay {seq} --model {corpus}/model/truncated.fsmodel --out {out}", 1,
     "truncated or damaged model file"},
    {"model_huge_payload", "replay {seq} --model {corpus}/model/huge_payload.fsmodel --out {out}", 1, "is implausible"},
    {"model_flipped_byte", "replay {seq} --model {shared}/flipped_byte.fsmodel --out {out}", 1, "flipped_byte.fsmodel"},
    {"model_evaluate_labels", "evaluate labels --dataset {data} --model {corpus}/model/random.fsmodel", 1,
     "not a facadeslam model file"},
    // Scene YAML (synth): nothing written
    {"scene_not_yaml", "synth --scene {corpus}/scene_yaml/not_yaml.yaml --out {out}", 1, "not_yaml.yaml"},
    {"scene_unknown_key", "synth --scene {corpus}/scene_yaml/unknown_key.yaml --out {out}", 1, "sede"},
    {"scene_missing_seed", "synth --scene {corpus}/scene_yaml/missing_seed.yaml --out {out}", 1,
     "key 'seed': expected a value"},
    {"scene_negative_frames", "synth --scene {corpus}/scene_yaml/negative_frames.yaml --out {out}", 1,
     "negative_frames.yaml"},
    {"scene_missing_camera", "synth --scene {corpus}/scene_yaml/missing_camera.yaml --out {out}", 1,
     "no-such-camera.yaml"},
    // A name longer than the file system allows (found by fuzz_scene_yaml:
    // std::filesystem's own error escaped the existence check).
    {"scene_camera_name_too_long", "synth --scene {corpus}/scene_yaml/camera_name_too_long.yaml --out {out}", 1,
     "key 'camera': expected an existing camera YAML file"},
    {"scene_empty", "synth --scene {corpus}/scene_yaml/empty.yaml --out {out}", 1, "empty.yaml"},
    {"scene_missing", "synth --scene {case}/none.yaml --out {out}", 1, "none.yaml: no such file"},
    // Trajectories (point 5)
    {"trajectory_all_equal_timestamps",
     "evaluate trajectory --gt {corpus}/trajectory/all_equal_timestamps.txt --est {corpus}/trajectory/good.txt", 1,
     "all_equal_timestamps.txt"},
    // A repeated line is read once, with a warning (exit 0).
    {"trajectory_duplicate_line",
     "evaluate trajectory --gt {corpus}/trajectory/duplicate_line.txt --est {corpus}/trajectory/good.txt", 0,
     "duplicate_line.txt: 1 repeated line(s) read once"},
    {"trajectory_garbage_bytes",
     "evaluate trajectory --gt {corpus}/trajectory/garbage_bytes.txt --est {corpus}/trajectory/good.txt", 1,
     "garbage_bytes.txt"},
    {"trajectory_nan_pose",
     "evaluate trajectory --gt {corpus}/trajectory/nan_pose.txt --est {corpus}/trajectory/good.txt", 1, "nan_pose.txt"},
    {"trajectory_zero_quaternion",
     "evaluate trajectory --gt {corpus}/trajectory/zero_quaternion.txt --est {corpus}/trajectory/good.txt", 1,
     "zero_quaternion.txt"},
    {"trajectory_no_overlap",
     "evaluate trajectory --gt {corpus}/trajectory/no_overlap.txt --est {corpus}/trajectory/good.txt", 1,
     "have a ground-truth pose within"},
    // KITTI pose files (12 numbers a line, no times): each error names the file and line.
    {"trajectory_kitti_wrong_column_count",
     "evaluate trajectory --gt {corpus}/trajectory/kitti_eleven_columns.txt --est {corpus}/trajectory/kitti_good.txt",
     1, "kitti_eleven_columns.txt:2: expected 12 numbers (row-major 3x4 pose [R | t]), got 11"},
    {"trajectory_kitti_nan",
     "evaluate trajectory --gt {corpus}/trajectory/kitti_good.txt --est {corpus}/trajectory/kitti_nan.txt", 1,
     "kitti_nan.txt:3: expected 12 numbers (row-major 3x4 pose [R | t]); 'nan' is not a finite number"},
    {"trajectory_kitti_non_numeric",
     "evaluate trajectory --gt {corpus}/trajectory/kitti_non_numeric.txt --est {corpus}/trajectory/kitti_good.txt", 1,
     "kitti_non_numeric.txt:2: expected 12 numbers (row-major 3x4 pose [R | t]); 'zero' is not a finite number"},
    {"trajectory_kitti_fewer_times_than_poses",
     "evaluate trajectory --gt {corpus}/trajectory/kitti_good.txt --gt-times {corpus}/trajectory/kitti_times_short.txt "
     "--est {corpus}/trajectory/good.txt",
     1, "kitti_times_short.txt: has 2 timestamps but"},
    // Line numbers against seconds would pair nothing sensible: a bad command line.
    {"trajectory_kitti_without_times_against_tum",
     "evaluate trajectory --gt {corpus}/trajectory/kitti_good.txt --est {corpus}/trajectory/good.txt", 2,
     "--gt-times: "},
    {"replay_gt_kitti_fewer_poses_than_frames", "replay {seq} --gt {corpus}/trajectory/kitti_two_poses.txt --out {out}",
     1, "kitti_two_poses.txt: has 2 poses but the sequence has frame 2"},
    {"replay_gt_one_pose", "replay {seq} --gt {corpus}/trajectory/one_pose.txt --out {out}", 1, "one_pose.txt"},
    {"replay_gt_garbage", "replay {seq} --gt {corpus}/trajectory/garbage_bytes.txt --out {out}", 1,
     "garbage_bytes.txt"},
    {"replay_gt_missing", "replay {seq} --gt {case}/missing.txt --out {out}", 1, "missing.txt"},
    // Genome files (exit 1) and strings (a bad command line, exit 2)
    {"genome_file_bad_character",
     "train --dataset {data} --genome {corpus}/genome/bad_character.txt --out {out}/m.fsmodel", 1, "bad_character.txt"},
    {"genome_file_too_short", "train --dataset {data} --genome {corpus}/genome/too_short.txt --out {out}/m.fsmodel", 1,
     "too_short.txt"},
    {"genome_file_binary", "train --dataset {data} --genome {corpus}/genome/binary.txt --out {out}/m.fsmodel", 1,
     "binary.txt"},
    {"genome_file_bad_json", "train --dataset {data} --genome {corpus}/genome/bad.json --out {out}/m.fsmodel", 1,
     "bad.json"},
    {"genome_string_short", "train --dataset {data} --genome 0101 --out {out}/m.fsmodel", 2, "--genome"},
    {"genome_string_neither", "evaluate labels --dataset {data} --genome nonsense.txt", 2, "neither a genome file"},
    {"genome_string_invariance", "evaluate invariance --images {data}/images --genome 0101", 2, "--genome"},
    // Labels (LabelMeFacade layout)
    {"labels_missing_png", "evaluate labels --dataset {shared}/missing_label", 1, "labels"},
    {"labels_unknown_colour", "evaluate labels --dataset {shared}/unknown_colour --json {case}/report.json", 1,
     "has the colour RGB(255, 255, 255), expected one of the nine class colours"},
    {"labels_unknown_colour_train", "train --dataset {shared}/unknown_colour --out {case}/m.fsmodel", 1,
     "pixel (0, 0) has the colour RGB(255, 255, 255)"},
    // The command line (point 6): exit code 2, one short line
    {"cli_stride_zero", "replay {seq} --stride 0 --out {out}", 2, "--stride"},
    {"cli_start_negative", "replay {seq} --start -5 --out {out}", 2, "--start"},
    {"cli_limit_negative", "replay {seq} --limit=-1 --out {out}", 2, "--limit"},
    {"cli_loop_zero", "replay {seq} --loop 0 --out {out}", 2, "--loop"},
    {"cli_resolution_small", "synth --scene {root}/configs/scenes/demo.yaml --resolution 12x12 --out {out}", 2,
     "--resolution"},
    {"cli_resolution_text", "synth --scene {root}/configs/scenes/demo.yaml --resolution big --out {out}", 2,
     "--resolution"},
    {"cli_invariance_step_zero", "evaluate invariance --images {data}/images --step 0", 2, "--step"},
    {"cli_invariance_margin_negative", "evaluate invariance --images {data}/images --margin -1", 2, "--margin"},
    {"cli_render_map_size", "render-map --map-ply {file} --out {out}/x.png --size 320by200", 2, "--size"},
    // Output locations checked before the work (point 1)
    {"out_replay_is_a_file", "replay {seq} --out {file}", 1, "it is a file"},
    {"out_replay_folder_of_other_files", "replay {seq} --semantics off --out {corpus}", 1,
     "must be new, empty or an earlier replay output"},
    {"out_synth_is_a_file", "synth --scene {root}/configs/scenes/demo.yaml --frames 3 --out {file}", 1, "it is a file"},
    {"out_synth_folder_of_other_files", "synth --scene {root}/configs/scenes/demo.yaml --frames 3 --out {old}", 1,
     "must be new, empty or an earlier synth output", Outputs::untouched},
    {"out_labels_json_is_a_folder", "evaluate labels --dataset {data} --json {case}", 1, "is a folder"},
    {"out_labels_confusion_unwritable",
     "evaluate labels --dataset {data} --confusion {file}/cm.png --model-out {out}/m.fsmodel", 1, "cm.png"},
    {"out_labels_model_out_unwritable", "evaluate labels --dataset {data} --model-out {file}/m.fsmodel", 1,
     "m.fsmodel"},
    {"out_invariance_plot_unwritable", "evaluate invariance --images {data}/images --plot {file}/p.png", 1, "p.png"},
    {"out_calibrate_plot_unwritable", "calibrate --images {data}/images --out {out}/camera.yaml --plot {file}/p.png", 1,
     "p.png"},
    {"out_render_map_unwritable", "render-map --map-ply {file} --out {file}/x.png", 1, "x.png"},
    {"out_train_unwritable", "train --dataset {data} --out {file}/m.fsmodel", 1, "m.fsmodel"},
    {"out_optimise_is_a_file", "optimise --dataset {data} --out {file}", 1, "it is a file"},
    {"optimise_seed_genome_short", "optimise --dataset {data} --seed-genome 0101 --out {out}", 2, "--seed-genome"},

    // Issue 41: outputs never overwrite inputs or the user's files (point 1).
    // replay/synth --out: a folder of the user's files, or one whose
    // report.json / synth.json is plain text, is refused whole.
    {"out_replay_folder_of_user_files", "replay {seq} --semantics off --out {mine}", 1, "--out holds '"},
    {"out_replay_plain_text_report", "replay {seq} --semantics off --out {case}/plain-report", 1,
     "'report.json', which is not a replay report"},
    {"out_replay_into_its_sequence", "replay {myseq} --semantics off --out {myseq}", 1,
     "--out is also the input SEQUENCE"},
    {"out_replay_into_the_sequence_parent", "replay {myseq} --semantics off --out {case}", 1,
     "--out holds the input SEQUENCE"},
    {"out_synth_folder_of_user_files", "synth --scene {root}/configs/scenes/demo.yaml --frames 3 --out {mine}", 1,
     "--out holds '"},
    {"out_synth_plain_text_manifest",
     "synth --scene {root}/configs/scenes/demo.yaml --frames 3 --out {case}/plain-synth", 1,
     "'synth.json', which is not a synth manifest"},
    // calibrate: --out a .yaml only, never a user's camera file, never among
    // the images (its plot beside it would be read as an image next time).
    {"out_calibrate_not_yaml", "calibrate --images {mine}/photos --out {mine}/thesis.tex", 1,
     "expected a camera file name ending in .yaml"},
    {"out_calibrate_user_camera_file", "calibrate --images {mine}/photos --out {mine}/camera.yaml", 1,
     "not a camera YAML written by facadeslam calibrate"},
    {"out_calibrate_plot_onto_an_image",
     "calibrate --images {mine}/photos --out {case}/c.yaml --plot {mine}/photos/a.png", 1, "--plot lies in --images"},
    {"out_calibrate_json_onto_an_image",
     "calibrate --images {mine}/photos --out {case}/c.yaml --json {mine}/photos/b.png", 1, "--json lies in --images"},
    {"out_calibrate_into_the_images", "calibrate --images {mine}/photos --out {mine}/photos/c.yaml", 1,
     "--out lies in --images"},
    {"out_calibrate_json_is_out", "calibrate --images {mine}/photos --out {case}/c.yaml --json {case}/c.yaml", 1,
     "--json is the same path as --out"},
    // replay --save-map: only a map, never an input, never another output.
    {"out_save_map_over_a_user_file", "replay {seq} --semantics off --save-map {mine}/notes.txt --out {out}", 1,
     "not a facadeslam map"},
    {"out_save_map_over_the_rgb_txt", "replay {myseq} --semantics off --save-map {myseq}/rgb.txt --out {out}", 1,
     "--save-map is also the input SEQUENCE's rgb.txt"},
    {"out_save_map_is_the_report", "replay {seq} --semantics off --save-map {out}/report.json --out {out}", 1,
     "--save-map is where --out puts a replay report"},
    {"out_save_map_is_out", "replay {seq} --semantics off --save-map {out} --out {out}", 1,
     "--save-map is the same path as --out"},
    {"out_save_map_is_a_folder", "replay {seq} --semantics off --save-map {mine}/photos --out {out}", 1,
     "--save-map is a folder"},
    // evaluate: an output that is an input is refused (it was overwritten, exit 0).
    {"out_trajectory_json_is_the_gt",
     "evaluate trajectory --gt {mine}/gt.txt --est {corpus}/trajectory/good.txt --json {mine}/gt.txt", 1,
     "--json is also the input --gt"},
    {"out_labels_json_is_test_txt", "evaluate labels --dataset {data} --json {data}/test.txt", 1,
     "--json is also the input --dataset's test.txt"},
    {"out_labels_confusion_over_a_label_image",
     "evaluate labels --dataset {data} --confusion {data}/labels/facade_0.png", 1,
     "--confusion lies in --dataset's labels/"},
    // --render outside --out is staged: a failed run leaves no render folder.
    {"out_render_outside_out_is_staged",
     "replay {shared}/mixed_size --camera {cam} --semantics off --render {case}/render --out {out}", 1,
     "image is 320x240"},
    {"out_render_folder_of_user_files", "replay {seq} --semantics off --render {mine} --out {out}", 1,
     "--render holds '"},
    {"out_optimise_among_user_files", "optimise --dataset {data} --out {mine}", 1, "--out holds '"},
    {"out_train_over_a_file_that_is_no_model", "train --dataset {data} --out {mine}/old.fsmodel", 1,
     "not a forest model"},
    {"out_render_map_over_its_input", "render-map --map-ply {mine}/photos/a.png --out {mine}/photos/a.png", 1,
     "--out is also the input --map-ply"},
    // A PNG is replaced only when this program drew it (its text chunk), not a user's photo.
    {"out_render_map_over_a_users_picture", "render-map --map-ply {file} --out {mine}/holiday.png", 1,
     "not a PNG picture drawn by facadeslam"},
    {"out_confusion_over_a_users_picture", "evaluate labels --dataset {data} --confusion {mine}/holiday.png", 1,
     "not a PNG picture drawn by facadeslam"},
    {"out_invariance_plot_over_a_users_picture", "evaluate invariance --images {data}/images --plot {mine}/holiday.png",
     1, "not a PNG picture drawn by facadeslam"},
    {"out_calibrate_plot_over_a_users_picture",
     "calibrate --images {mine}/photos --out {case}/c.yaml --plot {mine}/holiday.png", 1,
     "not a PNG picture drawn by facadeslam"},
    {"out_invariance_json_over_a_user_file", "evaluate invariance --images {data}/images --json {mine}/report.json", 1,
     "not an evaluate invariance report"},
    // Options (point 5): counts and seeds in range, no empty paths, clear lines.
    {"cli_out_empty_replay", "replay {seq} --out ''", 2, "--out: expected a path, got ''"},
    {"cli_out_empty_synth", "synth --scene {root}/configs/scenes/demo.yaml --out ''", 2, "--out: expected a path"},
    {"cli_out_empty_train", "train --dataset {data} --out ''", 2, "--out: expected a path"},
    {"cli_out_empty_optimise", "optimise --dataset {data} --out ''", 2, "--out: expected a path"},
    {"cli_out_empty_calibrate", "calibrate --images {mine}/photos --out ''", 2, "--out: expected a path"},
    {"cli_save_map_empty", "replay {seq} --save-map '' --out {out}", 2, "--save-map: expected a path"},
    {"cli_train_max_samples_negative", "train --dataset {data} --max-samples -1 --out {out}/m.fsmodel", 2,
     "--max-samples: expected a whole number in [0, "},
    {"cli_train_seed_negative", "train --dataset {data} --seed -1 --out {out}/m.fsmodel", 2,
     "--seed: expected a whole number in [0, "},
    {"cli_train_max_train_negative", "train --dataset {data} --max-train -3 --out {out}/m.fsmodel", 2,
     "--max-train: expected a whole number"},
    {"cli_labels_max_test_negative", "evaluate labels --dataset {data} --max-test -1", 2, "--max-test: expected"},
    {"cli_labels_seed_negative", "evaluate labels --dataset {data} --seed -1", 2, "--seed: expected"},
    {"cli_optimise_seed_negative", "optimise --dataset {data} --seed -1 --out {out}", 2, "--seed: expected"},
    {"cli_invariance_max_images_negative", "evaluate invariance --images {data}/images --max-images -1", 2,
     "--max-images: expected"},
    {"cli_render_every_zero", "replay {seq} --render {out}/r --render-every 0 --out {out}", 2,
     "--render-every: expected a whole number in [1, 1000000], got '0'"},
    {"cli_unknown_command", "frobnicate --out {out}", 2,
     "unknown command 'frobnicate' (expected one of: replay, evaluate"},
    {"cli_unknown_evaluate_command", "evaluate trajectroy --gt {corpus}/trajectory/good.txt", 2,
     "unknown evaluate command 'trajectroy' (expected one of: trajectory, labels, invariance)"},
    {"cli_missing_evaluate_command", "evaluate", 2,
     "missing evaluate command (expected one of: trajectory, labels, invariance)"},
    {"rgb_txt_huge_line_is_not_echoed", "replay {shared}/huge_line.txt --camera {cam} --out {out}", 1,
     "...' (1048576 bytes) is not a timestamp"},
    {"rgb_txt_fifo_image", "replay {shared}/fifo_list/rgb.txt --camera {cam} --out {out}", 1,
     "fifo.png is a FIFO (named pipe)"},
    // A FIFO named as an input is refused before it is opened (a reader
    // would wait forever on it).
    {"camera_is_a_fifo", "replay {seq} --camera {shared}/fifo_list/fifo.png --out {out}", 1,
     "fifo.png: is a FIFO (named pipe) (expected a camera YAML file)"},
    {"trajectory_gt_is_a_fifo",
     "evaluate trajectory --gt {shared}/fifo_list/fifo.png --est {corpus}/trajectory/good.txt", 1,
     "fifo.png: is a FIFO (named pipe) (expected a trajectory file)"},
    // Inputs confined to their folder (point 4).
    {"rgb_txt_outside_absolute", "replay {corpus}/rgb_txt/outside_absolute.txt --camera {cam} --out {out}", 1,
     "line 1: '/etc/passwd' leads outside"},
    {"rgb_txt_outside_relative", "replay {corpus}/rgb_txt/outside_relative.txt --camera {cam} --out {out}", 1,
     "leads outside"},
    {"rgb_txt_outside_frames", "replay {corpus}/rgb_txt/sub/outside_frames.txt --camera {cam} --out {out}", 1,
     "'../frames/a.png' leads outside"},
    // ... read on purpose: the frames are then read (and are placeholders).
    {"rgb_txt_outside_frames_allowed",
     "--allow-outside-paths replay {corpus}/rgb_txt/sub/outside_frames.txt --camera {cam} --on-corrupt stop --out "
     "{out}",
     1, "frames/a.png"},
    {"scene_camera_not_yaml", "synth --scene {corpus}/scene_yaml/camera_outside.yaml --out {out}", 1,
     "key 'camera': expected a camera YAML file (.yaml or .yml; pass --allow-outside-paths to read it anyway)"},
    {"scene_photo_outside", "synth --scene {corpus}/scene_yaml/photo_outside.yaml --out {out}", 1,
     "expected a path inside the photos folder"},
    {"scene_photo_not_an_image", "synth --scene {corpus}/scene_yaml/photo_not_an_image.yaml --out {out}", 1,
     "expected an image file (.jpg"},
    {"dataset_train_txt_outside", "train --dataset {shared}/outside_names --out {out}/m.fsmodel", 1,
     "train.txt: line 2: '../../../../../../../../etc/hostname' leads outside"},
    {"dataset_test_txt_outside",
     "evaluate labels --dataset {shared}/outside_names --model {root}/models/default.fsmodel", 1,
     "test.txt: line 1: '/etc/hostname' leads outside"},
    // --gt-labels missing a later frame fails before the first frame.
    {"gt_labels_missing_a_later_frame",
     "replay {seq} --semantics off --gt-labels {shared}/labels_missing_last --out {out}", 1,
     "the ground-truth label image of frame 000002.png does not exist"},
};

void write_bytes(const fs::path& path, const std::string& bytes) {
  fs::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << bytes;
}

std::string frame_name(int i) {
  char name[32];
  std::snprintf(name, sizeof name, "%06d.png", i);
  return name;
}

// A TUM sequence of `frames` frames in `folder` (rgb/, rgb.txt, camera.yaml).
void write_sequence(const fs::path& folder, int frames) {
  fs::create_directories(folder / "rgb");
  std::string list = "# timestamp filename\n";
  for (int i = 0; i < frames; ++i) {
    cv::imwrite((folder / "rgb" / frame_name(i)).string(), test::smooth_random_texture(640, 480, 7));
    list.append(std::to_string(i / 30.0)).append(" rgb/").append(frame_name(i)).append("\n");
  }
  write_bytes(folder / "rgb.txt", list);
  fs::copy_file(test::source_dir() / "configs" / "camera" / "synthetic-640x480.yaml", folder / "camera.yaml");
}

// The inputs made once for all cases.
class Shared {
 public:
  Shared() {
    write_sequence(root() / "seq", 3);
    // Image folders whose frame 1 is zero bytes, truncated, or of another size.
    for (const char* name : {"zero_byte", "truncated", "mixed_size"})
      for (int i = 0; i < 3; ++i) {
        fs::create_directories(root() / name);
        cv::imwrite((root() / name / frame_name(i)).string(), test::smooth_random_texture(640, 480, 7));
      }
    write_bytes(root() / "zero_byte" / frame_name(1), "");
    const std::string png = test::read_file_text(root() / "truncated" / frame_name(0));
    write_bytes(root() / "truncated" / frame_name(1), png.substr(0, png.size() / 3));
    cv::imwrite((root() / "mixed_size" / frame_name(1)).string(), test::smooth_random_texture(320, 240, 7));
    // A sequence whose synth.json counts other frames than its rgb.txt lists.
    write_sequence(root() / "mixed_manifest", 3);
    write_bytes(root() / "mixed_manifest" / "synth.json", "{\"generator\": \"facadeslam synth\", \"frames\": 5}\n");
    // The shipped model with one byte flipped mid-file.
    std::string model = test::read_file_text(test::source_dir() / "models" / "default.fsmodel");
    model[model.size() / 2] = static_cast<char>(~model[model.size() / 2]);
    write_bytes(root() / "flipped_byte.fsmodel", model);
    // Tiny LabelMeFacade-layout datasets: a good one, one missing a label PNG,
    // one with label pixels of no class colour.
    semantics::test_util::write_synthetic_dataset(root() / "data", 3, 2);
    semantics::test_util::write_synthetic_dataset(root() / "missing_label", 3, 2);
    for (const auto& entry : fs::directory_iterator(root() / "missing_label" / "labels")) {
      fs::remove(entry.path());
      break;
    }
    // Names in train.txt / test.txt leading out of the dataset.
    semantics::test_util::write_synthetic_dataset(root() / "outside_names", 3, 2);
    write_bytes(root() / "outside_names" / "train.txt", "facade_0\n../../../../../../../../etc/hostname\n");
    write_bytes(root() / "outside_names" / "test.txt", "/etc/hostname\n");
    // Labels for the first two of {seq}'s three frames only.
    fs::create_directories(root() / "labels_missing_last");
    for (int i = 0; i < 2; ++i)
      cv::imwrite((root() / "labels_missing_last" / frame_name(i)).string(),
                  synth::colours_from_label_ids(cv::Mat(480, 640, CV_8UC1, cv::Scalar(1))));
    // A list whose first line is 1 MB; a list naming a FIFO.
    write_bytes(root() / "huge_line.txt", std::string(1 << 20, '7') + " rgb/000000.png\n");
    fs::create_directories(root() / "fifo_list");
    ::mkfifo((root() / "fifo_list" / "fifo.png").c_str(), 0600);
    write_bytes(root() / "fifo_list" / "rgb.txt", "0.0 fifo.png\n");
    semantics::test_util::write_synthetic_dataset(root() / "unknown_colour", 3, 2);
    for (const auto& entry : fs::directory_iterator(root() / "unknown_colour" / "labels")) {
      cv::Mat label = cv::imread(entry.path().string(), cv::IMREAD_COLOR);
      label(cv::Rect(0, 0, label.cols / 2, label.rows)).setTo(cv::Scalar(255, 255, 255));
      cv::imwrite(entry.path().string(), label);
    }
  }
  const fs::path& root() const { return dir_.path(); }

 private:
  test::TempDir dir_;
};

Shared* g_shared = nullptr;

class BadInput : public ::testing::TestWithParam<Case> {
 public:
  static void SetUpTestSuite() { g_shared = new Shared; }
  static void TearDownTestSuite() {
    delete g_shared;
    g_shared = nullptr;
  }
};

std::string expand(std::string text, const std::map<std::string, fs::path>& places) {
  for (const auto& [key, path] : places)
    for (std::size_t at; (at = text.find(key)) != std::string::npos;)
      text.replace(at, key.size(), test::shell_quoted(path.string()));
  return text;
}

// Every file below `folder` with its size and a hash of its content (a
// failure lists the files, not their bytes).
std::map<std::string, std::string> snapshot(const fs::path& folder) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(folder)) {
    std::string what = "<folder>";
    if (entry.is_regular_file()) {
      const std::string content = test::read_file_text(entry.path());
      what = std::to_string(content.size()) + " bytes, hash " + std::to_string(std::hash<std::string>{}(content));
    }
    files[fs::relative(entry.path(), folder).string()] = what;
  }
  return files;
}

// Every file below `folder` with its size and modification time: cheap
// enough to take of the shared inputs around every case.
std::map<std::string, std::string> signature(const fs::path& folder) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(folder)) {
    const fs::file_status status = entry.symlink_status();
    std::string what = std::to_string(static_cast<int>(status.type()));
    if (fs::is_regular_file(status))
      what.append(" ")
          .append(std::to_string(entry.file_size()))
          .append(" ")
          .append(std::to_string(entry.last_write_time().time_since_epoch().count()));
    files[fs::relative(entry.path(), folder).string()] = what;
  }
  return files;
}

// The files of `snapshot` outside `scratch` and outside `allowed` (empty: none).
std::map<std::string, std::string> outside(std::map<std::string, std::string> files, const std::string& allowed) {
  for (auto it = files.begin(); it != files.end();) {
    const std::string& name = it->first;
    const auto below = [&](const std::string& folder) {
      return !folder.empty() && (name == folder || name.compare(0, folder.size() + 1, folder + "/") == 0);
    };
    it = below("scratch") || below(allowed) ? files.erase(it) : std::next(it);
  }
  return files;
}

// The user's own files a careless command line must not touch.
void write_user_files(const fs::path& dir, const std::string& arguments) {
  const fs::path mine = dir / "mine";
  test::write_text(mine / "notes.txt", "my notes\n");
  test::write_text(mine / "thesis.tex", "\\documentclass{article}\n");
  test::write_text(mine / "report.json", "my report, in plain text\n");
  test::write_text(mine / "synth.json", "my synth notes\n");
  test::write_text(mine / "camera.yaml", "# my own camera, measured by hand\nmodel: pinhole\nfx: 500\n");
  test::write_text(mine / "old.fsmodel", "not a model\n");
  fs::copy_file(test::source_dir() / "tests" / "bad_input" / "trajectory" / "good.txt", mine / "gt.txt");
  fs::create_directories(mine / "photos");
  cv::imwrite((mine / "photos" / "a.png").string(), test::smooth_random_texture(64, 48, 3));
  cv::imwrite((mine / "photos" / "b.png").string(), test::smooth_random_texture(64, 48, 4));
  cv::imwrite((mine / "holiday.png").string(), test::smooth_random_texture(64, 48, 5));
  test::write_text(dir / "plain-report" / "report.json", "my own notes, not a replay's\n");
  test::write_text(dir / "plain-synth" / "synth.json", "my own notes, not synth's\n");
  if (arguments.find("{myseq}") != std::string::npos) {
    fs::copy(g_shared->root() / "seq", dir / "myseq", fs::copy_options::recursive);
    test::write_text(dir / "myseq" / "report.json", "{\"mine\": true}\n");
  }
}

TEST_P(BadInput, FailsWithOneClearLineAndLeavesTheOutputs) {
  const Case& c = GetParam();
  const test::TempDir dir;
  const fs::path scratch = dir / "scratch", old = dir / "old";
  fs::create_directories(scratch);
  test::write_text(dir / "a-file", "not a folder\n");
  fs::create_directories(old);
  // An earlier replay's output as the output policy recognises it (core/util/output_policy.hpp).
  test::write_text(old / "report.json",
                   "{\"sequence\": \"old\", \"camera\": \"c.yaml\", \"mode\": \"synchronous\", "
                   "\"frames\": 3, \"initialised\": false}\n");
  test::write_text(old / "trajectory.txt", "0 0 0 0 0 0 0 1\n");
  const auto before = snapshot(old);
  write_user_files(dir.path(), c.arguments);
  const auto case_before = snapshot(dir.path());
  const auto shared_before = signature(g_shared->root());
  const fs::path corpus = test::source_dir() / "tests" / "bad_input";
  const std::map<std::string, fs::path> places = {
      {"{corpus}", corpus},
      {"{shared}", g_shared->root()},
      {"{seq}", g_shared->root() / "seq"},
      {"{cam}", g_shared->root() / "seq" / "camera.yaml"},
      {"{data}", g_shared->root() / "data"},
      {"{root}", test::source_dir()},
      {"{out}", dir / "out"},
      {"{old}", old},
      {"{file}", dir / "a-file"},
      {"{case}", dir.path()},
      {"{mine}", dir / "mine"},
      {"{myseq}", dir / "myseq"},
  };
  // -q: only warnings and errors on stderr.
  std::string arguments = "-q ";
  arguments.append(expand(c.arguments, places));
  const test::CliResult r = test::run_cli(FACADESLAM_BINARY, arguments, scratch);

  EXPECT_EQ(r.exit_code, c.exit_code) << r.err;
  EXPECT_THAT(r.err, HasSubstr(c.message));
  EXPECT_THAT(r.out, HasSubstr(c.stdout_message));
  if (c.exit_code == 1 || c.exit_code == 2) {
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_LT(r.err.size(), 600u) << r.err;
  }
  // No raw control bytes from hostile files on the terminal.
  EXPECT_EQ(std::count_if(r.err.begin(), r.err.end(),
                          [](char ch) { return static_cast<unsigned char>(ch) < 0x20 && ch != '\n'; }),
            0)
      << r.err;
  EXPECT_FALSE(fs::exists(dir / "out")) << "an output was left behind";
  if (c.outputs == Outputs::untouched) {
    EXPECT_EQ(snapshot(old), before) << "the earlier output folder was changed";
  }
  // Nothing else in the case's folder (the user's files, sequence, images)
  // or in the shared inputs changed.
  EXPECT_EQ(outside(snapshot(dir.path()), c.writes), outside(case_before, c.writes))
      << "a file outside the case's output was changed, made or removed";
  EXPECT_EQ(signature(g_shared->root()), shared_before) << "a shared input was changed";
  // No hidden temporary file or folder anywhere (staging folders, .tmp files).
  for (const auto& entry : fs::recursive_directory_iterator(dir.path()))
    EXPECT_NE(entry.path().filename().string().front(), '.') << "left behind: " << entry.path();
  for (const auto& entry : fs::directory_iterator(g_shared->root()))
    EXPECT_NE(entry.path().filename().string().front(), '.') << "left behind: " << entry.path();
}

INSTANTIATE_TEST_SUITE_P(Corpus, BadInput, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<Case>& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace facadeslam
