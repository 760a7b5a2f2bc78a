#pragma once
// A trained forest as a file: the forest plus what it needs to be used
// correctly later: which descriptor produced its rows (name and width), the
// genome (the modular descriptor's preprocessing and active values, and the
// forest settings for every descriptor) and the class table (id, name,
// label colour) its class ids refer to.
//
// The file is an OpenCV FileStorage document; a name ending in ".gz"
// (`model.yml.gz`) is gzip-compressed by OpenCV itself. Layout:
//   format: facadeslam-forest, version: 1, descriptor: "modular",
//   descriptor_width: 93, genome: "<211 0/1 characters>",
//   classes: [{id, name, rgb: [r, g, b]}, ...], forest: {RTrees}
#include <filesystem>
#include <string>
#include <vector>

#include "semantics/descriptor/genome.hpp"
#include "semantics/forest/random_forest.hpp"

namespace facadeslam::semantics {

struct ClassEntry {
  int id = 0;
  std::string name;
  cv::Vec3b rgb;  // label colour

  friend bool operator==(const ClassEntry&, const ClassEntry&) = default;
};

// LabelMeFacade's nine classes (core/map/semantic_classes.hpp), in id order.
std::vector<ClassEntry> labelmefacade_class_table();

struct ForestModel {
  std::string descriptor;  // point descriptor name ("modular", "sift", ...)
  Genome genome;
  std::vector<ClassEntry> classes;
  RandomForest forest;

  int descriptor_width() const { return forest.descriptor_width(); }
};

// Throws Error naming the file unless its name ends in .yml, .yaml, .xml or
// .json, optionally followed by .gz (checked before long runs that end by
// saving a model).
void require_model_file_name(const std::filesystem::path& path);

// Writes atomically (temp file + rename). The format follows the name:
// .yml/.yaml/.xml/.json, each optionally followed by .gz. Throws Error
// naming the file for an untrained forest, a forest class missing from the
// class table, or a failed write.
void save_forest_model(const std::filesystem::path& path, const ForestModel& model);

// Reads and checks a model file. A missing, damaged or truncated file, a
// missing or malformed field, or a forest inconsistent with its own header
// (width, classes) is an Error that names the file and what was expected.
ForestModel load_forest_model(const std::filesystem::path& path);

// What a caller needs from a model it loads.
struct ForestExpectation {
  std::string descriptor;
  int descriptor_width = 0;
  Genome genome;
  std::vector<ClassEntry> classes;  // empty: any class table
};

// load_forest_model() plus: the descriptor name and width, the genome and
// (when given) the class table must be the expected ones; otherwise an
// Error names the file, what it holds and what was expected.
ForestModel load_forest_model(const std::filesystem::path& path, const ForestExpectation& expected);

}  // namespace facadeslam::semantics
