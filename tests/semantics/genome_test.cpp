#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <random>
#include <set>

#include "core/util/error.hpp"
#include "semantics/descriptor/genome.hpp"
#include "semantics/descriptor/genome_io.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam::semantics {
namespace {

using test::error_of;

using ::testing::HasSubstr;

Genome random_genome(std::mt19937& rng) {
  Genome g;
  std::bernoulli_distribution coin(0.5);
  for (int i = 0; i < Genome::kBits; ++i) g.set_bit(i, coin(rng));
  return g;
}

int active_in(const DescriptorParams& p, Module m) {
  int n = 0;
  for (int i = 0; i < module_size(m); ++i) n += p.activation.test(static_cast<std::size_t>(module_offset(m) + i));
  return n;
}

bool active(const DescriptorParams& p, const std::string& name) {
  return p.activation.test(static_cast<std::size_t>(value_index(name).value()));
}

TEST(ModuleLayout, HasFourteenModulesAnd185NamedValues) {
  EXPECT_EQ(kModuleCount, 14);
  EXPECT_EQ(kValueCount, 185);
  EXPECT_EQ(module_offset(Module::gradient_angles) + module_size(Module::gradient_angles), 185);
  const auto& names = value_names();
  EXPECT_EQ(std::set<std::string>(names.begin(), names.end()).size(), 185u) << "names must be unique";
  for (int i = 0; i < kValueCount; ++i) EXPECT_EQ(value_index(value_name(i)), i);
  EXPECT_FALSE(value_index("no_such_value").has_value());
  EXPECT_EQ(value_name(0), "x_norm");
  EXPECT_EQ(value_name(module_offset(Module::mean_std) + 3), "std_c0");
  EXPECT_EQ(value_name(module_offset(Module::moments3) + 4 + 1), "eta21_c1");
  EXPECT_EQ(value_name(module_offset(Module::hu) + 14 + 2), "hu3_c2");
  EXPECT_EQ(value_name(module_offset(Module::gevers_l) + 4), "std_gevers_l2");
  EXPECT_EQ(value_name(module_offset(Module::geusebroek) + 3), "std_geusebroek_c");
  EXPECT_EQ(value_name(module_offset(Module::affine_invariants) + 9), "ami10_c0");
  EXPECT_EQ(value_name(module_offset(Module::singular_values) + 4), "sv2_c1");
  EXPECT_EQ(value_name(module_offset(Module::gradient_angles) + 15 + 10 + 0), "angle00_minus_11_c1");
  EXPECT_EQ(value_name(184), "angle21_minus_22_c2");
}

TEST(ModuleLayout, ModuleOfValueFollowsTheOffsets) {
  EXPECT_EQ(module_of_value(0), Module::position);
  EXPECT_EQ(module_of_value(1), Module::position);
  EXPECT_EQ(module_of_value(2), Module::mean_std);
  EXPECT_EQ(module_of_value(139), Module::singular_values);
  EXPECT_EQ(module_of_value(140), Module::gradient_angles);
  EXPECT_EQ(module_of_value(184), Module::gradient_angles);
  EXPECT_THROW(module_of_value(185), std::out_of_range);
}

TEST(Genome, ThesisBestDecodesToTables53To55) {
  const DescriptorParams p = Genome::thesis_best().decode();
  EXPECT_EQ(p.colour_space, ColourSpace::xyz);
  EXPECT_EQ(p.patch_radius, 10);
  EXPECT_EQ(p.gaussian_kernel, 7);
  EXPECT_DOUBLE_EQ(p.gaussian_sigma, 1.5);
  EXPECT_EQ(p.forest_size, 100);
  EXPECT_EQ(p.forest_depth, 35);
  EXPECT_EQ(p.split_variables, 16);
  EXPECT_EQ(p.canny_kernel, 5);
  EXPECT_EQ(p.canny_low_threshold, 65);
  EXPECT_EQ(p.canny_high_threshold(), 195);
  EXPECT_EQ(p.gradient_operator, GradientOperator::sobel);
  EXPECT_EQ(p.active_value_count(), 93);
  EXPECT_EQ(Genome::thesis_best().active_value_count(), 93);
  // Table 5.4, "Optimized" column, module by module.
  const std::array<int, kModuleCount> optimised{2, 4, 4, 5, 6, 10, 12, 4, 4, 2, 11, 2, 4, 23};
  for (int m = 0; m < kModuleCount; ++m)
    EXPECT_EQ(active_in(p, static_cast<Module>(m)), optimised[static_cast<std::size_t>(m)])
        << module_name(static_cast<Module>(m));
}

TEST(Genome, ThesisBestActivatesTheValuesOfTable55) {
  const DescriptorParams p = Genome::thesis_best().decode();
  for (const char* name : {"x_norm",
                           "y_norm",
                           "mean_c0",
                           "mean_c2",
                           "std_c0",
                           "std_c1",
                           "eta11_c0",
                           "eta02_c0",
                           "eta20_c2",
                           "eta11_c2",
                           "eta30_c0",
                           "eta03_c0",
                           "eta21_c1",
                           "eta21_c2",
                           "eta03_c2",
                           "eta22_c0",
                           "eta04_c0",
                           "eta04_c1",
                           "eta31_c2",
                           "eta22_c2",
                           "eta13_c2",
                           "eta50_c0",
                           "eta23_c0",
                           "eta14_c0",
                           "eta05_c0",
                           "eta50_c1",
                           "eta23_c1",
                           "eta05_c1",
                           "eta50_c2",
                           "eta41_c2",
                           "eta32_c2",
                           "hu2_c0",
                           "hu5_c0",
                           "hu7_c0",
                           "hu1_c1",
                           "hu3_c1",
                           "hu4_c1",
                           "hu5_c1",
                           "hu7_c1",
                           "hu4_c2",
                           "hu5_c2",
                           "hu6_c2",
                           "hu7_c2",
                           "mean_gevers_l1",
                           "mean_gevers_l3",
                           "std_gevers_l1",
                           "std_gevers_l3",
                           "mean_gevers_c1",
                           "std_gevers_c1",
                           "std_gevers_c2",
                           "std_gevers_c3",
                           "mean_geusebroek_h",
                           "std_geusebroek_c",
                           "ami2_c0",
                           "ami4_c0",
                           "ami8_c0",
                           "ami9_c0",
                           "ami1_c1",
                           "ami3_c1",
                           "ami6_c1",
                           "ami8_c1",
                           "ami1_c2",
                           "ami8_c2",
                           "ami9_c2",
                           "mean_edge_distance",
                           "std_edge_distance",
                           "sv1_c0",
                           "sv1_c1",
                           "sv2_c1",
                           "sv1_c2",
                           "angle11_c0",
                           "angle12_c0",
                           "angle21_c0",
                           "angle11_c1",
                           "angle21_c1",
                           "angle11_c2",
                           "angle12_c2",
                           "angle21_c2",
                           "angle00_minus_21_c0",
                           "angle11_minus_12_c0",
                           "angle11_minus_21_c0",
                           "angle11_minus_22_c0",
                           "angle12_minus_21_c0",
                           "angle21_minus_22_c0",
                           "angle00_minus_11_c1",
                           "angle00_minus_21_c1",
                           "angle11_minus_12_c1",
                           "angle11_minus_21_c1",
                           "angle12_minus_21_c1",
                           "angle00_minus_22_c2",
                           "angle11_minus_21_c2",
                           "angle11_minus_22_c2",
                           "angle12_minus_22_c2"})
    EXPECT_TRUE(active(p, name)) << name;
  for (const char* name : {"mean_c1", "std_c2", "eta20_c0", "hu1_c0", "mean_gevers_l2", "ami10_c1", "sv3_c0",
                           "angle00_c0", "angle22_c1", "angle00_minus_11_c0"})
    EXPECT_FALSE(active(p, name)) << name;
}

TEST(Genome, ParameterFieldsReadLeastSignificantBitFirst) {
  // Thesis eq. IV.1: x = sum b_i 2^i, b_0 being the field's first bit.
  const std::string text = Genome::thesis_best().to_string();
  EXPECT_EQ(text.substr(0, 26),
            "110"
            "111"
            "110"
            "010"
            "011"
            "101"
            "110"
            "1"
            "101"
            "0");
  Genome g;
  g.set_bit(0, true);
  EXPECT_EQ(g.decode().colour_space, ColourSpace::lab);
  g.set_bit(1, true);
  EXPECT_EQ(g.decode().colour_space, ColourSpace::xyz);
  g.set_bit(2, true);
  EXPECT_EQ(g.decode().colour_space, ColourSpace::opponent);
  g.set_bit(5, true);  // radius field 001 -> index 4 -> radius 7
  EXPECT_EQ(g.decode().patch_radius, 7);
  g.set_bit(25, true);
  EXPECT_EQ(g.decode().gradient_operator, GradientOperator::scharr);
  g.set_bit(26, true);
  EXPECT_TRUE(g.decode().activation.test(0));
}

TEST(Genome, AllZeroGenomeDecodesToTheFirstTableEntries) {
  const DescriptorParams p = Genome().decode();
  EXPECT_EQ(p.colour_space, ColourSpace::rgb);
  EXPECT_EQ(p.patch_radius, 3);
  EXPECT_EQ(p.gaussian_kernel, 1);
  EXPECT_DOUBLE_EQ(p.gaussian_sigma, 0.8);
  EXPECT_EQ(p.canny_kernel, 3);
  EXPECT_EQ(p.canny_low_threshold, 15);
  EXPECT_EQ(p.active_value_count(), 0);
}

TEST(Genome, EncodeInvertsDecodeForEveryTableValue) {
  DescriptorParams p = Genome::thesis_best().decode();
  for (const ColourSpace v : kColourSpaces) {
    p.colour_space = v;
    EXPECT_EQ(Genome::encode(p).decode(), p);
  }
  for (const int v : kPatchRadii) {
    p.patch_radius = v;
    EXPECT_EQ(Genome::encode(p).decode(), p);
  }
  for (const double v : kGaussianSigmas) {
    p.gaussian_sigma = v;
    EXPECT_EQ(Genome::encode(p).decode(), p);
  }
  for (const int v : kCannyLowThresholds) {
    p.canny_low_threshold = v;
    EXPECT_EQ(Genome::encode(p).decode(), p);
  }
  for (const int v : kSplitVariables) {
    p.split_variables = v;
    EXPECT_EQ(Genome::encode(p).decode(), p);
  }
  std::mt19937 rng(7);
  for (int i = 0; i < 200; ++i) {
    const Genome g = random_genome(rng);
    EXPECT_EQ(Genome::encode(g.decode()), g);
  }
}

TEST(Genome, EncodeRejectsValuesOutsideTheTables) {
  DescriptorParams p;
  p.patch_radius = 11;
  EXPECT_THAT(error_of([&] { Genome::encode(p); }), HasSubstr("patch_radius = 11"));
  p = {};
  p.gaussian_sigma = 2.0;
  EXPECT_THAT(error_of([&] { Genome::encode(p); }), HasSubstr("gaussian_sigma"));
  p = {};
  p.canny_low_threshold = 20;
  EXPECT_THAT(error_of([&] { Genome::encode(p); }), HasSubstr("canny_low_threshold"));
  p = {};
  p.forest_size = 90;
  EXPECT_THAT(error_of([&] { Genome::encode(p); }), HasSubstr("forest_size"));
}

TEST(Genome, TextFormRoundTrips) {
  std::mt19937 rng(11);
  for (int i = 0; i < 50; ++i) {
    const Genome g = random_genome(rng);
    const std::string text = g.to_string();
    ASSERT_EQ(text.size(), 211u);
    EXPECT_EQ(Genome::parse(text), g);
  }
  EXPECT_EQ(Genome::parse("  \n" + Genome::thesis_best().to_string() + "\n"), Genome::thesis_best());
}

TEST(Genome, ParseRejectsWrongLength) {
  const std::string text = Genome::thesis_best().to_string();
  EXPECT_THAT(error_of([&] { Genome::parse(text.substr(0, 210), "g.txt"); }),
              ::testing::AllOf(HasSubstr("g.txt: "), HasSubstr("211"), HasSubstr("got 210")));
  EXPECT_THAT(error_of([&] { Genome::parse(text + "0"); }), HasSubstr("got 212"));
  EXPECT_THAT(error_of([&] { Genome::parse(""); }), HasSubstr("got 0"));
}

TEST(Genome, ParseRejectsBadCharacters) {
  std::string text = Genome::thesis_best().to_string();
  text[10] = 'x';
  EXPECT_THAT(error_of([&] { Genome::parse(text); }),
              ::testing::AllOf(HasSubstr("character 10"), HasSubstr("gaussian_sigma"), HasSubstr("'x'")));
  text = Genome::thesis_best().to_string();
  text[26 + 2] = '2';
  EXPECT_THAT(error_of([&] { Genome::parse(text); }),
              ::testing::AllOf(HasSubstr("character 28"), HasSubstr("mean_c0")));
  text = Genome::thesis_best().to_string();
  text[100] = ' ';  // inner whitespace is not allowed
  EXPECT_THAT(error_of([&] { Genome::parse(text); }), HasSubstr("character 100"));
}

TEST(Genome, BitAccessChecksTheIndex) {
  Genome g;
  EXPECT_THROW(g.set_bit(211, true), std::out_of_range);
  EXPECT_THROW((void)g.bit(-1), std::out_of_range);
}

TEST(GenomeJson, RoundTripsThesisAndRandomGenomes) {
  EXPECT_EQ(genome_from_json(genome_to_json(Genome::thesis_best()).dump(), "t"), Genome::thesis_best());
  std::mt19937 rng(5);
  for (int i = 0; i < 30; ++i) {
    const Genome g = random_genome(rng);
    EXPECT_EQ(genome_from_json(genome_to_json(g).dump(), "t"), g);
  }
  EXPECT_EQ(genome_from_json(genome_to_json(Genome()).dump(), "t"), Genome());
}

TEST(GenomeJson, NamesFieldsAndActiveValues) {
  const std::string json = genome_to_json(Genome::thesis_best()).dump();
  EXPECT_THAT(json, HasSubstr("\"colour_space\":\"XYZ\""));
  EXPECT_THAT(json, HasSubstr("\"gaussian_sigma\":1.5"));
  EXPECT_THAT(json, HasSubstr("\"canny_high_threshold\":195"));
  EXPECT_THAT(json, HasSubstr("\"gradient_operator\":\"Sobel\""));
  EXPECT_THAT(json, HasSubstr("\"active_value_count\":93"));
  EXPECT_THAT(json, HasSubstr("\"sv2_c1\""));
  EXPECT_THAT(json, ::testing::Not(HasSubstr("\"sv3_c1\"")));
}

class GenomeJsonErrors : public ::testing::Test {
 protected:
  std::string base = json_text(genome_to_json(Genome::thesis_best()));
  std::string replaced(const std::string& from, const std::string& to) {
    std::string s = base;
    const auto at = s.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    s.replace(at, from.size(), to);
    return s;
  }
  std::string error(const std::string& json) {
    return error_of([&] { genome_from_json(json, "genome.json"); });
  }
};

TEST_F(GenomeJsonErrors, NotJson) { EXPECT_THAT(error("{ not json"), HasSubstr("genome.json: ")); }
TEST_F(GenomeJsonErrors, NotAnObject) {
  EXPECT_THAT(error("[1, 2]"), ::testing::AllOf(HasSubstr("genome.json: "), HasSubstr("JSON")));
}
TEST_F(GenomeJsonErrors, MissingKey) {
  EXPECT_THAT(error(replaced("\"patch_radius\": 10,", "")), HasSubstr("missing key 'patch_radius'"));
}
TEST_F(GenomeJsonErrors, UnknownKey) {
  EXPECT_THAT(error(replaced("\"patch_radius\"", "\"patch_radios\"")), HasSubstr("unknown key 'patch_radios'"));
}
TEST_F(GenomeJsonErrors, WrongType) {
  EXPECT_THAT(error(replaced("\"patch_radius\": 10", "\"patch_radius\": \"10\"")),
              HasSubstr("'patch_radius' must be an integer"));
}
TEST_F(GenomeJsonErrors, ValueOutsideTable) {
  EXPECT_THAT(error(replaced("\"patch_radius\": 10", "\"patch_radius\": 12")),
              ::testing::AllOf(HasSubstr("'patch_radius' = 12"), HasSubstr("3, 4, 5")));
  EXPECT_THAT(error(replaced("\"gaussian_sigma\": 1.5", "\"gaussian_sigma\": 1.6")), HasSubstr("gaussian_sigma"));
}
TEST_F(GenomeJsonErrors, UnknownColourSpace) {
  EXPECT_THAT(error(replaced("\"XYZ\"", "\"CMYK\"")), HasSubstr("'colour_space' = \"CMYK\""));
}
TEST_F(GenomeJsonErrors, UnknownGradientOperator) {
  EXPECT_THAT(error(replaced("\"Sobel\"", "\"Prewitt\"")), HasSubstr("gradient_operator"));
}
TEST_F(GenomeJsonErrors, InconsistentHighThreshold) {
  EXPECT_THAT(error(replaced("\"canny_high_threshold\": 195", "\"canny_high_threshold\": 130")),
              HasSubstr("3 x canny_low_threshold"));
}
TEST_F(GenomeJsonErrors, UnknownValueName) {
  EXPECT_THAT(error(replaced("\"sv2_c1\"", "\"sv9_c1\"")), HasSubstr("unknown value \"sv9_c1\""));
}
TEST_F(GenomeJsonErrors, DuplicateValueName) {
  EXPECT_THAT(error(replaced("\"sv2_c1\"", "\"sv1_c1\"")), HasSubstr("\"sv1_c1\" twice"));
}
TEST_F(GenomeJsonErrors, CountDisagreesWithValues) {
  EXPECT_THAT(error(replaced("\"active_value_count\": 93", "\"active_value_count\": 92")),
              HasSubstr("'active_value_count' = 92"));
}
TEST_F(GenomeJsonErrors, WrongFormatTag) {
  EXPECT_THAT(error(replaced("\"facadeslam-genome\"", "\"other\"")), HasSubstr("'format'"));
}

TEST(GenomeFiles, SaveAndLoadBothForms) {
  test::TempDir dir;
  std::mt19937 rng(3);
  const Genome g = random_genome(rng);
  save_genome(dir / "g.json", g);
  save_genome(dir / "g.txt", g);
  EXPECT_EQ(load_genome(dir / "g.json"), g);
  EXPECT_EQ(load_genome(dir / "g.txt"), g);
  save_genome(dir / "best.JSON", Genome::thesis_best());
  EXPECT_EQ(load_genome(dir / "best.JSON"), Genome::thesis_best());
}

TEST(GenomeFiles, ErrorsNameTheFile) {
  test::TempDir dir;
  EXPECT_THAT(error_of([&] { load_genome(dir / "missing.txt"); }),
              ::testing::AllOf(HasSubstr("missing.txt"), HasSubstr("cannot open")));
  test::write_text(dir / "short.txt", "0101\n");
  EXPECT_THAT(error_of([&] { load_genome(dir / "short.txt"); }),
              ::testing::AllOf(HasSubstr("short.txt: "), HasSubstr("got 4")));
  test::write_text(dir / "bad.json", "{\"format\": \"facadeslam-genome\"}");
  EXPECT_THAT(error_of([&] { load_genome(dir / "bad.json"); }),
              ::testing::AllOf(HasSubstr("bad.json: "), HasSubstr("missing key")));
}

}  // namespace
}  // namespace facadeslam::semantics
