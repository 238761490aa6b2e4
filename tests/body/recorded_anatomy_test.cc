// ReadRecordedAnatomy: what body.json's source says about the body, read back as the build
// decided it (the heel end from the "heel" and "toe tip" landmarks), and clear errors for a
// record that was edited into nonsense.
#include "ergo/body/recorded_anatomy.h"

#include <cmath>

#include <gtest/gtest.h>

#include "ergo/mesh/input_error.h"

namespace ergo {
namespace {

Json FootSource(double heel_z, double toe_z) {
  Json source = Json::object();
  source["anatomy"] = "foot";
  Json landmarks = Json::array();
  for (const auto& [name, z] : {std::pair<const char*, double>{"heel", heel_z},
                                {"ball", 0.5 * (heel_z + toe_z)},
                                {"toe tip", toe_z}}) {
    Json mark = Json::object();
    mark["name"] = name;
    mark["point_m"] = Json::array({0.01, 0.0, z});
    landmarks.push_back(mark);
  }
  source["landmarks"] = landmarks;
  return source;
}

TEST(Body, RecordedFootTellsItsHeelEndFromItsLandmarks) {
  const RecordedAnatomy at_min = ReadRecordedAnatomy(FootSource(-0.12, 0.13), "body.json");
  EXPECT_EQ(at_min.anatomy, Anatomy::kFoot);
  ASSERT_TRUE(at_min.heel_end.has_value());
  EXPECT_EQ(*at_min.heel_end, HeelEnd::kMinZ);
  // The same foot turned end for end.
  const RecordedAnatomy at_max = ReadRecordedAnatomy(FootSource(0.13, -0.12), "body.json");
  ASSERT_TRUE(at_max.heel_end.has_value());
  EXPECT_EQ(*at_max.heel_end, HeelEnd::kMaxZ);
}

// The heel's bisector as measured on the scan (ergo_body build writes it for a foot whose heel
// could be bisected) reads back in radians with its medial side; a record without it (bodies
// built before) says nothing of it.
TEST(Body, RecordedFootGivesBackTheHeelsBisectorMeasuredOnTheScan) {
  Json source = FootSource(-0.12, 0.13);
  EXPECT_FALSE(ReadRecordedAnatomy(source, "body.json").heel.has_value());
  source["heel_eversion_deg"] = 0.9;
  source["medial_side"] = "-x";
  const RecordedAnatomy recorded = ReadRecordedAnatomy(source, "body.json");
  ASSERT_TRUE(recorded.heel.has_value());
  EXPECT_DOUBLE_EQ(recorded.heel->eversion, 0.9 * M_PI / 180);
  EXPECT_EQ(recorded.heel->medial_sign, -1);
  source["medial_side"] = "left";
  EXPECT_THROW(ReadRecordedAnatomy(source, "body.json"), InputError);
  source["medial_side"] = "+x";
  source["heel_eversion_deg"] = "upright";
  EXPECT_THROW(ReadRecordedAnatomy(source, "body.json"), InputError);
}

TEST(Body, RecordWithoutAnatomyOrWithoutBothEndsSaysNothingOfTheHeel) {
  // A body built from a shape or without --anatomy records no anatomy.
  Json shape = Json::object();
  shape["mode"] = "shape";
  EXPECT_EQ(ReadRecordedAnatomy(shape, "body.json").anatomy, Anatomy::kNone);
  EXPECT_FALSE(ReadRecordedAnatomy(shape, "body.json").heel_end.has_value());
  // A seat has no heel; a foot missing its toe tip cannot say which end is which.
  Json seat = Json::object();
  seat["anatomy"] = "seat";
  EXPECT_EQ(ReadRecordedAnatomy(seat, "body.json").anatomy, Anatomy::kSeat);
  Json foot = FootSource(0, 0.25);
  foot["landmarks"].erase(2);
  const RecordedAnatomy partial = ReadRecordedAnatomy(foot, "body.json");
  EXPECT_EQ(partial.anatomy, Anatomy::kFoot);
  EXPECT_FALSE(partial.heel_end.has_value());
}

TEST(Body, EditedRecordIsRefusedNamingTheFile) {
  Json unknown = Json::object();
  unknown["anatomy"] = "paw";
  EXPECT_THROW(ReadRecordedAnatomy(unknown, "dir/body.json"), InputError);
  Json foot = FootSource(0, 0.25);
  foot["landmarks"][0]["point_m"] = Json::array({0.0, "up"});
  try {
    ReadRecordedAnatomy(foot, "dir/body.json");
    FAIL() << "a malformed landmark was accepted";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("dir/body.json"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("heel"), std::string::npos) << error.what();
  }
  Json not_a_list = FootSource(0, 0.25);
  not_a_list["landmarks"] = 3;
  EXPECT_THROW(ReadRecordedAnatomy(not_a_list, "dir/body.json"), InputError);
}

}  // namespace
}  // namespace ergo
