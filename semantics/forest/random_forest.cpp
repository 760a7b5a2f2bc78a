#include "semantics/forest/random_forest.hpp"

#include <algorithm>
#include <string>

#include "core/util/error.hpp"
#include "semantics/forest/opencv_reason.hpp"
#include "semantics/text.hpp"

namespace facadeslam::semantics {
namespace {

void require_samples(const cv::Mat& samples, int width, const char* what) {
  if (samples.type() != CV_32F || samples.dims != 2) {
    throw Error(cat(what, ": descriptor rows must be a 2-D CV_32F matrix"));
  }
  if (width > 0 && samples.cols != width) {
    throw Error(cat(what, ": rows have ", samples.cols, " values, the forest was trained on ", width));
  }
}

}  // namespace

RandomForest RandomForest::train(const cv::Mat& samples, const std::vector<int>& labels, const ForestParams& params) {
  validate(params);
  require_samples(samples, 0, "random forest training");
  if (samples.rows == 0 || samples.cols == 0) throw Error("random forest training: no training rows");
  if (labels.size() != static_cast<std::size_t>(samples.rows))
    throw Error(cat("random forest training: ", labels.size(), " labels for ", samples.rows, " rows"));
  if (std::any_of(labels.begin(), labels.end(), [](int l) { return l < 0; }))
    throw Error("random forest training: class ids must be >= 0");
  cv::Point bad;
  if (!cv::checkRange(samples, true, &bad))
    throw Error(cat("random forest training: row ", bad.y, " has a non-finite value"));

  cv::Ptr<cv::ml::RTrees> model = cv::ml::RTrees::create();
  model->setMaxDepth(params.max_depth);
  model->setMinSampleCount(params.min_sample_count);
  model->setActiveVarCount(std::min(params.split_variables, samples.cols));
  model->setTermCriteria(cv::TermCriteria(cv::TermCriteria::MAX_ITER, params.trees, 0.0));
  model->setCalculateVarImportance(false);
  model->setUseSurrogates(false);
  model->setRegressionAccuracy(0.0f);
  // Integer responses make OpenCV treat the problem as classification.
  const cv::Mat responses(static_cast<int>(labels.size()), 1, CV_32S, const_cast<int*>(labels.data()));
  // RTrees draws its bootstrap samples and split variables from the
  // thread's cv::theRNG(): seed it for reproducible forests and give the
  // caller's generator back afterwards.
  cv::RNG& rng = cv::theRNG();
  const cv::RNG saved = rng;
  rng.state = params.seed;
  try {
    const auto data = cv::ml::TrainData::create(samples, cv::ml::ROW_SAMPLE, responses.clone());
    const bool trained = model->train(data);
    rng = saved;
    if (!trained) throw Error("random forest training: OpenCV reported failure");
  } catch (const cv::Exception& e) {
    rng = saved;
    throw Error(cat("random forest training failed: ", opencv_reason(e)));
  }
  return from_model(model);
}

RandomForest RandomForest::from_model(cv::Ptr<cv::ml::RTrees> model) {
  if (model.empty() || !model->isTrained() || !model->isClassifier())
    throw Error("not a trained random-forest classifier");
  RandomForest forest;
  forest.model_ = model;
  forest.width_ = model->getVarCount();
  forest.trees_ = static_cast<int>(model->getRoots().size());
  if (forest.width_ <= 0 || forest.trees_ <= 0) throw Error("the random forest has no trees or no input values");
  // getVotes' first row lists the class labels of its columns.
  cv::Mat table;
  try {
    model->getVotes(cv::Mat::zeros(1, forest.width_, CV_32F), table, cv::ml::DTrees::PREDICT_MAX_VOTE);
  } catch (const cv::Exception& e) {
    throw Error(cat("the random forest cannot vote: ", opencv_reason(e)));
  }
  if (table.type() != CV_32S || table.rows != 2 || table.cols < 1) throw Error("the random forest has no class list");
  for (int c = 0; c < table.cols; ++c) forest.classes_.push_back(table.at<int>(0, c));
  forest.flatten();
  return forest;
}

RandomForest RandomForest::from_nodes(int width, std::vector<int> classes, std::vector<Node> nodes,
                                      std::vector<int> roots) {
  RandomForest forest;
  forest.width_ = width;
  forest.trees_ = static_cast<int>(roots.size());
  forest.classes_ = std::move(classes);
  forest.nodes_ = std::move(nodes);
  forest.roots_ = std::move(roots);
  forest.check();
  return forest;
}

void RandomForest::flatten() {
  const std::vector<cv::ml::DTrees::Node>& nodes = model_->getNodes();
  const std::vector<cv::ml::DTrees::Split>& splits = model_->getSplits();
  const int split_count = static_cast<int>(splits.size());
  nodes_.clear();
  nodes_.reserve(nodes.size());
  for (const cv::ml::DTrees::Node& n : nodes) {
    Node f;
    if (n.split < 0) {
      f.leaf_class = n.classIdx;
    } else {
      if (n.split >= split_count) throw Error("a node of the random forest has no valid split");
      const cv::ml::DTrees::Split& s = splits[static_cast<std::size_t>(n.split)];
      // A negative index would pass for a leaf; width_ makes check() reject it.
      f.var = s.varIdx >= 0 ? s.varIdx : width_;
      f.threshold = s.c;
      f.low = s.inversed ? n.right : n.left;
      f.high = s.inversed ? n.left : n.right;
    }
    nodes_.push_back(f);
  }
  roots_ = model_->getRoots();
  check();
}

void RandomForest::check() const {
  if (width_ <= 0 || trees_ <= 0 || roots_.empty() || nodes_.empty())
    throw Error("the random forest has no trees or no input values");
  if (classes_.empty() || !std::is_sorted(classes_.begin(), classes_.end()) ||
      std::adjacent_find(classes_.begin(), classes_.end()) != classes_.end() || classes_.front() < 0)
    throw Error("the random forest's class list is not ascending distinct non-negative ids");
  const int node_count = static_cast<int>(nodes_.size()), class_count = static_cast<int>(classes_.size());
  for (int i = 0; i < node_count; ++i) {
    const Node& n = nodes_[static_cast<std::size_t>(i)];
    if (n.var < 0) {
      if (n.leaf_class < 0 || n.leaf_class >= class_count)
        throw Error("a leaf of the random forest has no valid class");
      continue;
    }
    if (n.var >= width_) throw Error("a split of the random forest reads a value outside the descriptor");
    // Children after their parent: no walk can loop (see Node).
    if (n.low <= i || n.low >= node_count || n.high <= i || n.high >= node_count)
      throw Error("a node of the random forest points outside its tree");
  }
  for (const int r : roots_)
    if (r < 0 || r >= node_count) throw Error("a tree root of the random forest is outside the tree");
}

cv::Mat RandomForest::votes(const cv::Mat& samples) const {
  if (!trained()) throw Error("random forest: not trained");
  require_samples(samples, width_, "random forest prediction");
  cv::Mat table = cv::Mat::zeros(samples.rows, static_cast<int>(classes_.size()), CV_32S);
  const Node* nodes = nodes_.data();
  for (int r = 0; r < samples.rows; ++r) {
    const float* x = samples.ptr<float>(r);
    int* count = table.ptr<int>(r);
    for (const int root : roots_) {
      const Node* n = nodes + root;
      // check() guarantees children after parents, so this ends at a leaf.
      while (n->var >= 0) n = nodes + (x[n->var] <= n->threshold ? n->low : n->high);
      ++count[n->leaf_class];
    }
  }
  return table;
}

cv::Mat RandomForest::opencv_votes(const cv::Mat& samples) const {
  if (model_.empty()) throw Error("random forest: no OpenCV model behind this forest");
  require_samples(samples, width_, "random forest prediction");
  if (samples.rows == 0) return cv::Mat(0, static_cast<int>(classes_.size()), CV_32S);
  cv::Mat table;
  try {
    model_->getVotes(samples, table, cv::ml::DTrees::PREDICT_MAX_VOTE);
  } catch (const cv::Exception& e) {
    throw Error(cat("random forest prediction failed: ", opencv_reason(e)));
  }
  return table.rowRange(1, table.rows);
}

std::vector<int> RandomForest::predict(const cv::Mat& samples, cv::Mat& probabilities) const {
  const cv::Mat v = votes(samples);
  v.convertTo(probabilities, CV_32F, 1.0 / trees_);
  std::vector<int> labels(static_cast<std::size_t>(v.rows));
  for (int r = 0; r < v.rows; ++r) {
    const int* row = v.ptr<int>(r);
    // Columns are in ascending id order, so the first maximum is the smaller id.
    labels[static_cast<std::size_t>(r)] = classes_[static_cast<std::size_t>(std::max_element(row, row + v.cols) - row)];
  }
  return labels;
}

std::vector<int> RandomForest::predict(const cv::Mat& samples) const {
  cv::Mat unused;
  return predict(samples, unused);
}

cv::Mat RandomForest::probabilities(const cv::Mat& samples) const {
  cv::Mat p;
  predict(samples, p);
  return p;
}

}  // namespace facadeslam::semantics
