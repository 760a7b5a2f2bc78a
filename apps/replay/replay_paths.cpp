#include "apps/replay/replay_paths.hpp"

#include "apps/cli_support.hpp"
#include "apps/output_kinds.hpp"
#include "core/util/output_policy.hpp"
#include "core/util/path_checks.hpp"

namespace facadeslam::apps {

void check_replay_paths(const ReplayPaths& p) {
  OutputPlan plan;
  // An image folder is read whole (a file put there would be a frame next
  // time); a list or a video is one input, its images are confined to its
  // folder (sequences/tum_list_source.cpp).
  if (is_existing_folder(p.sequence)) {
    plan.input(p.sequence / "rgb.txt", "SEQUENCE's rgb.txt");
    plan.input_folder_read_whole(p.sequence, "SEQUENCE");
  } else
    plan.input(p.sequence, "SEQUENCE");
  plan.input(p.camera, "--camera");
  plan.input(p.config, "--config");
  plan.input(p.gt, "--gt");
  plan.input_folder_read_whole(p.gt_labels, "--gt-labels");
  plan.input(p.load_map, "--load-map");
  plan.input(p.model, "--model");
  plan.input(p.grey_model, "--grey-model");
  plan.input(p.semantics_config, "--semantics-config");
  plan.output_folder(p.out, "--out", replay_folder_layout());
  plan.output_file(p.save_map, "--save-map", map_file_kind());
  plan.output_folder(p.render, "--render", render_folder_layout());
  plan.check();
  // Inputs that are there but are no readable file (a FIFO would block).
  require_readable_if_present(p.camera, "a camera YAML file");
  require_readable_if_present(p.config, "a SLAM settings YAML file");
  require_readable_if_present(p.gt, "a ground-truth trajectory (TUM or KITTI)");
  require_readable_if_present(p.load_map, "a map file (.fslmap)");
  require_readable_if_present(p.model, "a forest model (.fsmodel)");
  require_readable_if_present(p.grey_model, "a forest model (.fsmodel)");
  require_readable_if_present(p.semantics_config, "a semantic settings YAML file");
}

}  // namespace facadeslam::apps
