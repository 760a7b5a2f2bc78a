// The output policy: outputs replace only files of their own kind, output
// folders only earlier outputs, never an input, and two outputs of one run
// never collide.
#include "core/util/output_policy.hpp"
#include "core/util/png_signature.hpp"

#include <fstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/support/test_support.hpp"

namespace facadeslam {
namespace {

namespace fs = std::filesystem;
using test::error_of;
using ::testing::AllOf;
using ::testing::HasSubstr;

void put_file(const fs::path& path, const std::string& bytes) {
  fs::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << bytes;
}

// A PNG's signature and header chunk (its CRC not checked here), then data.
const std::string kUsersPng = std::string("\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR", 16) + std::string(13 + 4, '\x01') +
                              std::string("\0\0\0\x04IDATdataCRC!", 16);
std::string signed_png(const std::string& png) {
  const std::vector<unsigned char> bytes = sign_png(std::vector<unsigned char>(png.begin(), png.end()));
  return std::string(bytes.begin(), bytes.end());
}
const std::string kPng = signed_png(kUsersPng);

OutputFileKind report_kind() { return json_object_with_keys("a test report", {"frames", "mode"}); }
OutputFileKind map_kind() { return file_starting_with("a test map", "FSLAMMAP"); }

std::shared_ptr<const OutputFolderLayout> pictures() {
  return std::make_shared<const OutputFolderLayout>(
      OutputFolderLayout{"pictures", {file_entry("*.png", png_file("a PNG picture"))}});
}

std::shared_ptr<const OutputFolderLayout> layout() {
  return std::make_shared<const OutputFolderLayout>(OutputFolderLayout{
      "an earlier test output",
      {file_entry("report.json", report_kind()), file_entry("trajectory.txt", numbered_lines("a trajectory")),
       folder_entry("frames", pictures()), file_entry("*.fslmap", map_kind(), /*every_run=*/false)}});
}

TEST(OutputFileKinds, AreRecognisedByContentNotByName) {
  test::TempDir dir;
  put_file(dir / "report.json", "{\"frames\": 3, \"mode\": \"sync\", \"more\": [1, 2]}");
  put_file(dir / "plain.json", "plain text, not JSON");
  put_file(dir / "other.json", "{\"frames\": 3}");
  put_file(dir / "a.png", kPng);
  put_file(dir / "fake.png", "not a picture");
  put_file(dir / "photo.png", kUsersPng);
  put_file(dir / "t.txt", "# timestamp tx ty tz qx qy qz qw\n1.0 0 0 0 0 0 0 1\n\n2.5 1 2 3 0 0 0 1\n");
  put_file(dir / "notes.txt", "1.0 is a number but\nthis line is not\n");
  put_file(dir / "map.fslmap", std::string("FSLAMMAP\x04\0\0\0", 12));
  put_file(dir / "camera.yaml", "# Calibrated by `facadeslam calibrate`\n# facadeslam camera\nfx: 1\n");
  put_file(dir / "binary.bin", std::string("text\0text", 9));
  EXPECT_TRUE(report_kind().recognises(dir / "report.json"));
  EXPECT_FALSE(report_kind().recognises(dir / "plain.json"));
  EXPECT_FALSE(report_kind().recognises(dir / "other.json")) << "a JSON object without the report's keys";
  EXPECT_TRUE(json_object_with_keys("any JSON object", {}).recognises(dir / "other.json"));
  EXPECT_TRUE(png_file("png").recognises(dir / "a.png"));
  EXPECT_FALSE(png_file("png").recognises(dir / "fake.png"));
  EXPECT_FALSE(png_file("png").recognises(dir / "photo.png")) << "a PNG this program did not write";
  EXPECT_THROW(sign_png(std::vector<unsigned char>(5, 0)), Error);
  EXPECT_TRUE(numbered_lines("trajectory").recognises(dir / "t.txt"));
  EXPECT_FALSE(numbered_lines("trajectory").recognises(dir / "notes.txt"));
  EXPECT_TRUE(map_kind().recognises(dir / "map.fslmap"));
  EXPECT_FALSE(map_kind().recognises(dir / "a.png"));
  EXPECT_TRUE(text_with_line("camera", "# facadeslam camera").recognises(dir / "camera.yaml"));
  EXPECT_FALSE(text_with_line("camera", "# facadeslam camera").recognises(dir / "notes.txt"));
  EXPECT_TRUE(text_file("text").recognises(dir / "notes.txt"));
  EXPECT_FALSE(text_file("text").recognises(dir / "binary.bin"));
  EXPECT_TRUE(any_of("either", {png_file("png"), map_kind()}).recognises(dir / "map.fslmap"));
  EXPECT_FALSE(any_of("either", {png_file("png"), map_kind()}).recognises(dir / "plain.json"));
}

TEST(OutputFolder, AnEarlierOutputIsReplaceableAnythingElseIsNot) {
  test::TempDir dir;
  const fs::path out = dir / "out";
  put_file(out / "report.json", "{\"frames\": 3, \"mode\": \"sync\"}");
  put_file(out / "trajectory.txt", "1 0 0 0 0 0 0 1\n");
  put_file(out / "frames" / "000001.png", kPng);
  put_file(out / "saved.fslmap", "FSLAMMAP....");
  EXPECT_EQ(foreign_entry(out, *layout()), "");
  OutputPlan plan;
  plan.output_folder(out, "--out", layout());
  EXPECT_NO_THROW(plan.check());

  // A user's file beside them; a report.json that is plain text; a file of
  // the user's in a subfolder; a hidden folder; a symbolic link.
  put_file(out / "notes.txt", "mine");
  EXPECT_THAT(error_of([&] { plan.check(); }), AllOf(HasSubstr(out.string()), HasSubstr("--out holds 'notes.txt'"),
                                                     HasSubstr("an earlier test output")));
  fs::remove(out / "notes.txt");
  put_file(out / "report.json", "plain text");
  EXPECT_THAT(foreign_entry(out, *layout()), HasSubstr("'report.json', which is not a test report"));
  put_file(out / "report.json", "{\"frames\": 3, \"mode\": \"sync\"}");
  put_file(out / "frames" / "holiday.jpg", "jpeg");
  EXPECT_THAT(foreign_entry(out, *layout()), HasSubstr("'frames/holiday.jpg'"));
  fs::remove(out / "frames" / "holiday.jpg");
  fs::create_directories(out / ".git");
  EXPECT_THAT(foreign_entry(out, *layout()), HasSubstr("'.git'"));
  fs::remove(out / ".git");
  fs::create_symlink(dir / "elsewhere.fslmap", out / "link.fslmap");
  EXPECT_THAT(foreign_entry(out, *layout()), HasSubstr("symbolic link"));
  fs::remove(out / "link.fslmap");
  EXPECT_EQ(foreign_entry(out, *layout()), "");

  // Absent and empty folders are fine; a file is not a folder.
  EXPECT_EQ(foreign_entry(dir / "empty", *layout()), "");
  put_file(dir / "a-file", "x");
  OutputPlan file_plan;
  file_plan.output_folder(dir / "a-file", "--out", layout());
  EXPECT_THAT(error_of([&] { file_plan.check(); }), HasSubstr("it is a file"));
}

TEST(OutputFile, ReplacesOnlyAFileOfItsKind) {
  test::TempDir dir;
  put_file(dir / "earlier.fslmap", "FSLAMMAP....");
  put_file(dir / "thesis.tex", "\\documentclass{article}");
  fs::create_directories(dir / "folder");
  OutputPlan earlier, foreign, folder, fresh;
  earlier.output_file(dir / "earlier.fslmap", "--save-map", map_kind());
  EXPECT_NO_THROW(earlier.check());
  foreign.output_file(dir / "thesis.tex", "--save-map", map_kind());
  EXPECT_THAT(error_of([&] { foreign.check(); }),
              AllOf(HasSubstr((dir / "thesis.tex").string()), HasSubstr("not a test map"), HasSubstr("refusing")));
  folder.output_file(dir / "folder", "--save-map", map_kind());
  EXPECT_THAT(error_of([&] { folder.check(); }), HasSubstr("is a folder"));
  fresh.output_file(dir / "new.fslmap", "--save-map", map_kind());
  EXPECT_NO_THROW(fresh.check());
}

TEST(OutputPlan, AnOutputIsNeverAnInputNorHoldsOne) {
  test::TempDir dir;
  const fs::path seq = dir / "seq";
  put_file(seq / "rgb.txt", "1 rgb/1.png\n");
  put_file(dir / "gt.txt", "1 0 0 0 0 0 0 1\n");
  fs::create_directories(dir / "images");
  {
    OutputPlan plan;  // the output file is the input (even as a trajectory: of its kind)
    plan.input(dir / "gt.txt", "--gt");
    plan.output_file(dir / "gt.txt", "--json", numbered_lines("a trajectory"));
    EXPECT_THAT(error_of([&] { plan.check(); }), HasSubstr("--json is also the input --gt"));
  }
  {
    OutputPlan plan;  // reached through a symbolic link
    fs::create_directory_symlink(seq, dir / "link-to-seq");
    plan.input(seq / "rgb.txt", "SEQUENCE");
    plan.output_folder(dir / "link-to-seq", "--out", layout());
    EXPECT_THAT(error_of([&] { plan.check(); }), HasSubstr("--out holds the input SEQUENCE"));
  }
  {
    OutputPlan plan;  // the output folder is the input folder
    plan.input(seq, "SEQUENCE");
    plan.output_folder(seq, "--out", layout());
    EXPECT_THAT(error_of([&] { plan.check(); }), HasSubstr("--out is also the input SEQUENCE"));
  }
  {
    OutputPlan plan;  // a file among images that are all read
    plan.input_folder_read_whole(dir / "images", "--images");
    plan.output_file(dir / "images" / "plot.png", "--plot", png_file("a PNG picture"));
    EXPECT_THAT(error_of([&] { plan.check(); }), HasSubstr("--plot lies in --images"));
  }
  {
    OutputPlan plan;  // beside the inputs is fine
    plan.input(dir / "gt.txt", "--gt");
    plan.input_folder_read_whole(dir / "images", "--images");
    plan.output_file(dir / "report.json", "--json", report_kind());
    plan.output_folder(dir / "out", "--out", layout());
    EXPECT_NO_THROW(plan.check());
  }
}

TEST(OutputPlan, TwoOutputsNeverCollide) {
  test::TempDir dir;
  const fs::path out = dir / "out";
  const auto plan_with = [&](const fs::path& map, const std::string& option = "--save-map") {
    OutputPlan plan;
    plan.output_folder(out, "--out", layout());
    plan.output_file(map, option, map_kind());
    return plan;
  };
  EXPECT_THAT(error_of([&] { plan_with(out).check(); }), HasSubstr("--save-map is the same path as --out"));
  EXPECT_THAT(error_of([&] { plan_with(out / "report.json").check(); }),
              HasSubstr("--save-map is where --out puts a test report"));
  EXPECT_THAT(error_of([&] { plan_with(out / "frames" / "x.png").check(); }), HasSubstr("is where --out puts"));
  EXPECT_THAT(error_of([&] { plan_with(out / "notes" / "x.fslmap").check(); }),
              HasSubstr("under a name an earlier test output never holds"));
  // A map under a name the folder leaves free is staged with it.
  EXPECT_NO_THROW(plan_with(out / "mine.fslmap").check());
  OutputPlan same;
  same.output_file(dir / "a.json", "--json", report_kind());
  same.output_file(dir / "a.json", "--plot", png_file("a PNG picture"));
  EXPECT_THAT(error_of([&] { same.check(); }), HasSubstr("--plot is the same path as --json"));
}

TEST(ResolvedPaths, FollowLinksAndNeverThrow) {
  test::TempDir dir;
  fs::create_directories(dir / "real" / "sub");
  fs::create_directory_symlink(dir / "real", dir / "link");
  EXPECT_TRUE(lies_within(dir / "link" / "sub" / "new.txt", dir / "real"));
  EXPECT_TRUE(lies_within(dir / "real", dir / "real"));
  EXPECT_FALSE(lies_within(dir / "real" / ".." / "other", dir / "real"));
  EXPECT_FALSE(lies_within(dir / "realm", dir / "real")) << "a name that starts like the folder's";
  EXPECT_NO_THROW(resolved_path(dir / std::string(5000, 'x')));
}

}  // namespace
}  // namespace facadeslam
