#pragma once
// A contact sheet: a few frames of a sequence side by side, each colour image
// above its label map, with a title — for eyeballing a scene
// (docs/synth-contact-sheet.png).
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace facadeslam::synth {

// `count` frame indices spread evenly over [0, frames), first and last
// included (fewer when frames < count).
std::vector<int> contact_sheet_frames(int frames, int count);

class ContactSheet {
 public:
  // Each tile is scaled to `tile_width` pixels wide.
  ContactSheet(std::string title, int tile_width = 256);
  // colour: CV_8UC3; labels_bgr: the label colours, CV_8UC3.
  void add(const std::string& caption, const cv::Mat& colour, const cv::Mat& labels_bgr);
  bool empty() const { return tiles_.empty(); }
  cv::Mat image() const;

 private:
  std::string title_;
  int tile_width_;
  std::vector<cv::Mat> tiles_;
};

}  // namespace facadeslam::synth
