#include "semantics/evaluation/confusion_matrix.hpp"

#include <limits>

#include "core/util/error.hpp"
#include "semantics/text.hpp"

namespace facadeslam::semantics {
namespace {

double ratio(std::uint64_t a, std::uint64_t b) {
  return b == 0 ? std::numeric_limits<double>::quiet_NaN() : static_cast<double>(a) / static_cast<double>(b);
}

}  // namespace

ConfusionMatrix::ConfusionMatrix(int classes) : classes_(classes) {
  if (classes < 1) throw Error("confusion matrix: needs at least one class");
  cells_.assign(static_cast<std::size_t>(classes) * static_cast<std::size_t>(classes), 0);
}

void ConfusionMatrix::add(int truth, int predicted, std::uint64_t count) {
  if (truth < 0 || truth >= classes_ || predicted < 0 || predicted >= classes_)
    throw Error(cat("confusion matrix: class pair (", truth, ", ", predicted, ") outside 0..", classes_ - 1));
  cells_[static_cast<std::size_t>(truth * classes_ + predicted)] += count;
  total_ += count;
}

std::uint64_t ConfusionMatrix::at(int truth, int predicted) const {
  if (truth < 0 || truth >= classes_ || predicted < 0 || predicted >= classes_)
    throw Error(cat("confusion matrix: class pair (", truth, ", ", predicted, ") outside 0..", classes_ - 1));
  return cells_[static_cast<std::size_t>(truth * classes_ + predicted)];
}

std::uint64_t ConfusionMatrix::truth_count(int k) const {
  std::uint64_t sum = 0;
  for (int p = 0; p < classes_; ++p) sum += at(k, p);
  return sum;
}

std::uint64_t ConfusionMatrix::predicted_count(int k) const {
  std::uint64_t sum = 0;
  for (int t = 0; t < classes_; ++t) sum += at(t, k);
  return sum;
}

ClassMetrics ConfusionMatrix::metrics(int k) const {
  ClassMetrics m;
  m.tp = at(k, k);
  m.fn = truth_count(k) - m.tp;
  m.fp = predicted_count(k) - m.tp;
  m.tn = total_ - m.tp - m.fn - m.fp;
  m.accuracy = ratio(m.tp + m.tn, total_);
  m.precision = ratio(m.tp, m.tp + m.fp);
  m.recall = ratio(m.tp, m.tp + m.fn);
  m.specificity = ratio(m.tn, m.tn + m.fp);
  m.npv = ratio(m.tn, m.tn + m.fn);
  m.f1 = ratio(2 * m.tp, 2 * m.tp + m.fp + m.fn);
  return m;
}

double ConfusionMatrix::overall_recognition_rate() const {
  std::uint64_t trace = 0;
  for (int k = 0; k < classes_; ++k) trace += at(k, k);
  return ratio(trace, total_);
}

double ConfusionMatrix::average_recognition_rate() const {
  double sum = 0;
  int present = 0;
  for (int k = 0; k < classes_; ++k) {
    if (truth_count(k) == 0) continue;
    sum += metrics(k).recall;
    ++present;
  }
  return present ? sum / present : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace facadeslam::semantics
