#pragma once
// Confusion matrix and the per-class figures of thesis III.4.7. Row = true
// class, column = predicted class. For class k: TP = C[k][k], FN = rest of
// row k, FP = rest of column k, TN = everything else, and
//   accuracy = (TP+TN)/N, precision = TP/(TP+FP), recall = TP/(TP+FN),
//   specificity = TN/(TN+FP), NPV = TN/(TN+FN), F1 = 2TP/(2TP+FP+FN).
// A ratio whose denominator is 0 is undefined: NaN (null in JSON), not 0,
// so that "never predicted" is not mistaken for "always wrong".
// Overall recognition rate = trace / N. Average recognition rate = mean
// recall over the classes that occur in the ground truth (a class absent
// from the test set has no recall to average).
#include <cstdint>
#include <vector>

namespace facadeslam::semantics {

struct ClassMetrics {
  std::uint64_t tp = 0, fp = 0, fn = 0, tn = 0;
  double accuracy = 0, precision = 0, recall = 0, specificity = 0, npv = 0, f1 = 0;
};

class ConfusionMatrix {
 public:
  explicit ConfusionMatrix(int classes);

  int classes() const { return classes_; }
  // Throws Error for a class id outside 0..classes-1.
  void add(int truth, int predicted, std::uint64_t count = 1);
  std::uint64_t at(int truth, int predicted) const;
  std::uint64_t total() const { return total_; }
  std::uint64_t truth_count(int k) const;      // row sum
  std::uint64_t predicted_count(int k) const;  // column sum

  ClassMetrics metrics(int k) const;
  double overall_recognition_rate() const;  // NaN when empty
  double average_recognition_rate() const;  // NaN when empty

 private:
  int classes_;
  std::vector<std::uint64_t> cells_;
  std::uint64_t total_ = 0;
};

}  // namespace facadeslam::semantics
