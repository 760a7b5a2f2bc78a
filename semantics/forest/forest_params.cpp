#include "semantics/forest/forest_params.hpp"

#include <string>

#include "core/util/error.hpp"
#include "semantics/text.hpp"

namespace facadeslam::semantics {
namespace {

void require_range(const char* field, int value, int low, int high) {
  if (value >= low && value <= high) return;
  throw Error(cat("forest parameter ", field, " = ", value, " is outside ", low, "..", high));
}

}  // namespace

ForestParams forest_params(const DescriptorParams& params) {
  ForestParams forest;
  forest.trees = params.forest_size;
  forest.max_depth = params.forest_depth;
  forest.split_variables = params.split_variables;
  return forest;
}

void validate(const ForestParams& params) {
  require_range("trees", params.trees, 1, 10000);
  require_range("max_depth", params.max_depth, 1, 1000);
  require_range("split_variables", params.split_variables, 1, 1 << 20);
  require_range("min_sample_count", params.min_sample_count, 1, 1 << 30);
}

}  // namespace facadeslam::semantics
