#include "slam/init/two_view_result.hpp"

namespace facadeslam {

const char* to_string(InitStatus status) {
  switch (status) {
    case InitStatus::need_more_parallax: return "need_more_parallax";
    case InitStatus::too_few_tracks: return "too_few_tracks";
    case InitStatus::degenerate: return "degenerate";
    case InitStatus::success: return "success";
  }
  return "unknown";
}

const char* to_string(TwoViewModel model) {
  switch (model) {
    case TwoViewModel::homography: return "homography";
    case TwoViewModel::essential: return "essential";
  }
  return "unknown";
}

}  // namespace facadeslam
