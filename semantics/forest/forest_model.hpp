#pragma once
// A trained forest as a file: the forest plus what it needs to be used
// correctly later: which descriptor produced its rows (name and width), the
// genome (the modular descriptor's preprocessing and active values, and the
// forest settings for every descriptor) and the class table (id, name,
// label colour) its class ids refer to.
//
// Two file formats, chosen by the name:
// - `.fsmodel` (what `facadeslam train` writes and the replay loads): our
//   own compact binary form, zlib-compressed and versioned
//   (fsmodel_format.hpp); under half the size of the other (tested).
// - an OpenCV FileStorage document (`evaluate labels --model-out`); a name
//   ending in ".gz" (`model.yml.gz`) is gzip-compressed by OpenCV itself.
//   It keeps OpenCV's own RTrees for inspection. Layout:
//   format: facadeslam-forest, version: 1, descriptor: "modular",
//   descriptor_width: 93, genome: "<211 0/1 characters>",
//   classes: [{id, name, rgb: [r, g, b]}, ...], forest: {RTrees}
#include <cstdint>
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

// What a forest was trained on: colour photos, or photos turned grey (a
// model for grey cameras, `train --grey`). Used on the other kind it labels
// badly without any error (the colour model on grey frames calls a third of
// a street sky), so loading one for the wrong kind is refused. Unknown for
// .fsmodel files of format 1 and for OpenCV documents.
enum class ModelImages : std::uint8_t { colour = 0, grey = 1, unknown = 255 };
const char* model_images_name(ModelImages images);  // "colour", "grey", "unknown"

// LabelMeFacade's nine classes (core/map/semantic_classes.hpp), in id order.
std::vector<ClassEntry> labelmefacade_class_table();

struct ForestModel {
  std::string descriptor;  // point descriptor name ("modular", "sift", ...)
  Genome genome;
  std::vector<ClassEntry> classes;
  ModelImages images = ModelImages::unknown;
  // The settings the forest was trained with. A FileStorage model does not
  // record the seed (read back as 0).
  ForestParams params;
  RandomForest forest;

  int descriptor_width() const { return forest.descriptor_width(); }
};

// Throws Error naming the file unless its name ends in .fsmodel, or .yml,
// .yaml, .xml or .json, optionally followed by .gz (checked before long runs
// that end by saving a model).
void require_model_file_name(const std::filesystem::path& path);

// Writes atomically (temp file + rename). The format follows the name:
// .fsmodel, or .yml/.yaml/.xml/.json, each optionally followed by .gz.
// A .fsmodel model can only be saved as .fsmodel (it has no OpenCV trees
// behind it). Throws Error
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

// load_forest_model() plus check_forest_model().
ForestModel load_forest_model(const std::filesystem::path& path, const ForestExpectation& expected);

// The descriptor name and width, the genome and (when given) the class
// table of `model` (read from `path`) must be the expected ones; otherwise
// an Error names the file, what it holds and what was expected.
void check_forest_model(const std::filesystem::path& path, const ForestModel& model, const ForestExpectation& expected);

}  // namespace facadeslam::semantics
