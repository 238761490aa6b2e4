// Population files (problems/population.h): the shipped shoe population reads as written; a
// file read, written and read again is the same population; every malformed file is refused
// naming the file, the member and the fix; the generator's Latin hypercube covers every
// range's strata once, is fixed by its seed and gives the support and the mean body their
// values.
#include "problems/population.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>

#include <gtest/gtest.h>

#include "ergo/mesh/input_error.h"
#include "tests/support/test_paths.h"

namespace ergo {
namespace {

namespace fs = std::filesystem;

TEST(ProblemsPopulation, TheShippedShoePopulationReadsAsWritten) {
  const PopulationSpec spec = ReadPopulationFile(testing::SourcePath("data/shoe_population.json"));
  ASSERT_EQ(spec.bodies.size(), 4u);
  EXPECT_EQ(spec.bodies[0].name, "small-soft");
  EXPECT_EQ(spec.bodies[2].flags.at("shoe_modulus_scale"), "1.25");
  EXPECT_EQ(spec.bodies[3].flags.at("shoe_lean_torque"), "8");
  EXPECT_EQ(spec.flags.at("robust_placements"), "3");
  EXPECT_EQ(spec.support.at("shoe_foot_length"), "0.27");
  EXPECT_FALSE(spec.mean_body.empty());
  // The flagfile is resolved against the population file's folder.
  EXPECT_TRUE(fs::path(spec.flagfile).is_absolute());
  EXPECT_TRUE(fs::equivalent(spec.flagfile, testing::SourcePath("data/shoe.flags")));
  for (const PopulationBody& body : spec.bodies) EXPECT_EQ(body.weight, 1);
}

TEST(ProblemsPopulation, AWrittenPopulationReadsBackTheSame) {
  const std::string dir = testing::MakeScratchDir("population");
  PopulationSpec spec = ReadPopulationFile(testing::SourcePath("data/shoe_population.json"));
  spec.bodies[1].weight = 2.5;
  spec.bodies[1].flags["body_dir"] = dir + "/feet/medium";  // a path flag, absolute
  WriteJsonFile(dir + "/copy.json", PopulationJson(spec));
  const PopulationSpec again = ReadPopulationFile(dir + "/copy.json");
  EXPECT_EQ(again.description, spec.description);
  EXPECT_EQ(again.flagfile, spec.flagfile);
  EXPECT_EQ(again.flags, spec.flags);
  EXPECT_EQ(again.support, spec.support);
  EXPECT_EQ(again.mean_body, spec.mean_body);
  ASSERT_EQ(again.bodies.size(), spec.bodies.size());
  for (size_t b = 0; b < spec.bodies.size(); ++b) {
    EXPECT_EQ(again.bodies[b].name, spec.bodies[b].name);
    EXPECT_EQ(again.bodies[b].weight, spec.bodies[b].weight);
    EXPECT_EQ(again.bodies[b].flags, spec.bodies[b].flags);
  }
  fs::remove_all(dir);
}

TEST(ProblemsPopulation, RelativePathFlagsAreResolvedAgainstTheFile) {
  const std::string dir = testing::MakeScratchDir("population");
  std::ofstream(dir + "/p.json")
      << R"({"bodies": [{"name": "scan", "flags": {"skin": "scans/foot.stl", "skin_unit": "mm"}}]})";
  const PopulationSpec spec = ReadPopulationFile(dir + "/p.json");
  EXPECT_EQ(fs::path(spec.bodies[0].flags.at("skin")), fs::path(dir) / "scans/foot.stl");
  EXPECT_EQ(spec.bodies[0].flags.at("skin_unit"), "mm");  // not a path: as written
  EXPECT_TRUE(spec.flagfile.empty());
  fs::remove_all(dir);
}

struct BadFile {
  const char* text;
  const char* expected;  // in the message, besides the file's name
};

TEST(ProblemsPopulation, MalformedFilesAreRefusedNamingTheMemberAndTheFix) {
  const std::string dir = testing::MakeScratchDir("population");
  const std::vector<BadFile> cases = {
      {"{\"bodies\": [", "line 1"},
      {"[1, 2]", "not an object"},
      {"{}", "\"bodies\""},
      {"{\"bodies\": []}", "non-empty array"},
      {"{\"bodies\": [3]}", "bodies[0]"},
      {"{\"bodies\": [{\"weight\": 1}]}", "\"name\""},
      {"{\"bodies\": [{\"name\": \"a b\"}]}", "is not usable"},
      {"{\"bodies\": [{\"name\": \"../x\"}]}", "is not usable"},
      {"{\"bodies\": [{\"name\": \"a\"}, {\"name\": \"a\"}]}", "appears twice"},
      {"{\"bodies\": [{\"name\": \"a\", \"weight\": 0}]}", "positive"},
      {"{\"bodies\": [{\"name\": \"a\", \"weight\": \"heavy\"}]}", "\"weight\""},
      {"{\"bodies\": [{\"name\": \"a\", \"flags\": {\"--mass\": 1}}]}", "not a flag's name"},
      {"{\"bodies\": [{\"name\": \"a\", \"flags\": {\"mass\": [1]}}]}", "not a string or number"},
      {"{\"bodies\": [{\"name\": \"a\", \"flags\": {\"mass\": \"1\\n2\"}}]}", "line break"},
      {"{\"bodies\": [{\"name\": \"a\", \"flags\": [1]}]}", "not an object"},
      {"{\"flagfile\": \"missing.flags\", \"bodies\": [{\"name\": \"a\"}]}", "is not a file"},
      {"{\"support\": 1, \"bodies\": [{\"name\": \"a\"}]}", "member \"support\""},
  };
  int index = 0;
  for (const BadFile& bad : cases) {
    const std::string path = dir + "/bad" + std::to_string(index++) + ".json";
    std::ofstream(path) << bad.text;
    try {
      ReadPopulationFile(path);
      ADD_FAILURE() << "accepted: " << bad.text;
    } catch (const InputError& error) {
      const std::string message = error.what();
      EXPECT_NE(message.find(path), std::string::npos) << message;
      EXPECT_NE(message.find(bad.expected), std::string::npos) << bad.text << " → " << message;
    }
  }
  EXPECT_THROW(ReadPopulationFile(dir + "/absent.json"), InputError);
  fs::remove_all(dir);
}

TEST(ProblemsPopulation, TheLatinHypercubeCoversEveryStratumOnceAndFollowsItsSeed) {
  PopulationGenerator generator;
  generator.flagfile = "shoe.flags";
  generator.count = 8;
  generator.ranges = {{"shoe_foot_length", 0.23, 0.29}, {"shoe_modulus_scale", 0.7, 1.3}};
  generator.fixed = {{"robust_placements", "1"}};
  generator.support_at = {{"shoe_foot_length", "high"}};
  const PopulationSpec spec = GeneratePopulation(generator);
  ASSERT_EQ(spec.bodies.size(), 8u);
  EXPECT_EQ(spec.bodies[0].name, "shoe-1");
  EXPECT_EQ(spec.bodies[7].name, "shoe-8");
  for (const FlagRange& range : generator.ranges) {
    // Body values are the strata's centres low + (k + 0.5)/8 (high − low), each once.
    std::set<int> strata;
    for (const PopulationBody& body : spec.bodies) {
      const double value = std::stod(body.flags.at(range.flag));
      const double k = (value - range.low) / (range.high - range.low) * 8 - 0.5;
      EXPECT_NEAR(k, std::round(k), 1e-4) << range.flag << " " << value;
      strata.insert(static_cast<int>(std::round(k)));
      EXPECT_EQ(body.flags.at("robust_placements"), "1");
    }
    EXPECT_EQ(strata.size(), 8u) << range.flag;
    EXPECT_EQ(*strata.begin(), 0);
    EXPECT_EQ(*strata.rbegin(), 7);
    EXPECT_NEAR(std::stod(spec.mean_body.at(range.flag)), 0.5 * (range.low + range.high), 1e-12);
  }
  EXPECT_EQ(spec.support.at("shoe_foot_length"), "0.29");
  EXPECT_EQ(spec.support.count("shoe_modulus_scale"), 0u);  // the scene's default
  // The same seed, the same bodies; another seed shuffles the pairing.
  const PopulationSpec same = GeneratePopulation(generator);
  generator.seed = 2;
  const PopulationSpec other = GeneratePopulation(generator);
  int differing = 0;
  for (size_t b = 0; b < spec.bodies.size(); ++b) {
    EXPECT_EQ(same.bodies[b].flags, spec.bodies[b].flags);
    differing += other.bodies[b].flags != spec.bodies[b].flags;
  }
  EXPECT_GT(differing, 0);
}

TEST(ProblemsPopulation, RangesAndGeneratorOptionsAreChecked) {
  const FlagRange range = ParseFlagRange("shoe_body_mass=60:90", "--vary");
  EXPECT_EQ(range.flag, "shoe_body_mass");
  EXPECT_EQ(range.low, 60);
  EXPECT_EQ(range.high, 90);
  for (const char* bad : {"shoe_body_mass", "shoe_body_mass=60", "=1:2", "Mass=1:2",
                          "shoe_body_mass=a:2", "shoe_body_mass=1:", "shoe_body_mass=3:2"})
    EXPECT_THROW(ParseFlagRange(bad, "--vary"), InputError) << bad;
  PopulationGenerator generator;
  EXPECT_THROW(GeneratePopulation(generator), InputError);  // no range
  generator.ranges = {{"shoe_body_mass", 60, 90}};
  generator.count = 0;
  EXPECT_THROW(GeneratePopulation(generator), InputError);
  generator.count = 1;  // one body: the range's midpoint
  EXPECT_EQ(GeneratePopulation(generator).bodies[0].flags.at("shoe_body_mass"), "75");
}

}  // namespace
}  // namespace ergo
