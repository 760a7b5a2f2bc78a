#pragma once
// A random forest classifier over OpenCV's ml::RTrees, for descriptor rows.
// Class probabilities are vote shares: each tree votes for one class, so a
// row's probabilities sum to 1 and say how unanimous the forest is (the
// semantic worker drops labels the forest is unsure of).
//
// Prediction walks a flat copy of the trees rather than calling
// RTrees::getVotes, which predicts tree by tree through a generic path
// (~130 us per row for 100 trees; the flat walk is an order of magnitude
// faster and gives the same votes, checked by a unit test). The flat nodes
// are also what a .fsmodel file stores (fsmodel_format.hpp): a forest read
// back from one has no OpenCV model behind it and predicts the same.
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/ml.hpp>

#include "semantics/forest/forest_params.hpp"

namespace facadeslam::semantics {

class RandomForest {
 public:
  // One tree node: a split "value <= threshold goes to `low`, else `high`"
  // (OpenCV's inverted splits already swapped), or a leaf (var < 0) voting
  // for column `leaf_class` of classes(). Children always come after their
  // parent in the node array (OpenCV builds trees depth first), which is
  // what makes every walk end, even through a damaged file.
  struct Node {
    int var = -1;
    float threshold = 0.0f;
    int low = -1, high = -1;
    int leaf_class = -1;
    friend bool operator==(const Node&, const Node&) = default;
  };

  RandomForest() = default;

  // `samples`: CV_32F, one descriptor per row, finite values. `labels`: the
  // class id (>= 0) of each row. Throws Error on empty or inconsistent input.
  // Training is deterministic: the same data and parameters give the same
  // forest (RTrees seeds its own generator).
  static RandomForest train(const cv::Mat& samples, const std::vector<int>& labels, const ForestParams& params);

  // Wraps a trained classifier read from a model file; throws Error (without
  // a file name: the caller adds it) when it is not a trained RTrees
  // classifier.
  static RandomForest from_model(cv::Ptr<cv::ml::RTrees> model);

  // A forest from its flat nodes (what a .fsmodel file holds): `classes`
  // ascending non-negative ids, `roots` one node index per tree. Throws
  // Error (without a file name) for anything inconsistent: a split reading
  // outside the width, a child not after its parent or outside the array, a
  // leaf without a valid class.
  static RandomForest from_nodes(int width, std::vector<int> classes, std::vector<Node> nodes, std::vector<int> roots);

  bool trained() const { return !nodes_.empty(); }
  // Number of values per descriptor row the forest expects.
  int descriptor_width() const { return width_; }
  int tree_count() const { return trees_; }
  // Class ids seen in training, ascending: the columns of probabilities().
  const std::vector<int>& classes() const { return classes_; }

  // rows x classes().size() CV_32F vote shares. `samples` must have
  // descriptor_width() CV_32F columns (Error otherwise).
  cv::Mat probabilities(const cv::Mat& samples) const;
  // The class id with the most votes per row; ties go to the smaller id.
  std::vector<int> predict(const cv::Mat& samples) const;
  // Both at once (one pass over the trees).
  std::vector<int> predict(const cv::Mat& samples, cv::Mat& probabilities) const;

  const std::vector<Node>& nodes() const { return nodes_; }
  const std::vector<int>& roots() const { return roots_; }

  // The OpenCV classifier it was trained as or read from; empty for a
  // forest made from_nodes().
  const cv::Ptr<cv::ml::RTrees>& model() const { return model_; }

  // CV_32S rows x classes().size(): trees voting for each class.
  cv::Mat votes(const cv::Mat& samples) const;
  // The same through OpenCV's RTrees::getVotes (reference for tests; Error
  // without an OpenCV model).
  cv::Mat opencv_votes(const cv::Mat& samples) const;

 private:
  void flatten();      // OpenCV's trees as nodes_ and roots_, then check()
  void check() const;  // throws Error on inconsistent nodes (damaged model)

  cv::Ptr<cv::ml::RTrees> model_;
  std::vector<int> classes_;
  std::vector<Node> nodes_;
  std::vector<int> roots_;
  int width_ = 0;
  int trees_ = 0;
};

}  // namespace facadeslam::semantics
