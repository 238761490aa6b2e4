// What a body directory says about its body's anatomy: body.json's "source" records, for a
// body built from a scan with --anatomy (body_build.h), the anatomy's name and its landmarks
// in ergo's frame. A tool that reads the directory later (ergo_simulate) learns from them
// whether the body is a foot and which end of z its heel is at, the build's own decision.
#pragma once

#include <optional>
#include <string>

#include "ergo/body/anatomical_priors.h"
#include "ergo/body/heel_bisector.h"
#include "ergo/mesh/json.h"

namespace ergo {

struct RecordedAnatomy {
  Anatomy anatomy = Anatomy::kNone;
  // A foot's heel end: kMinZ or kMaxZ from its "heel" and "toe tip" landmarks; empty when
  // either is missing or they share a z.
  std::optional<HeelEnd> heel_end;
  // A foot's heel bisector as measured on the scan before meshing (heel_bisector.h), with its
  // medial side; empty for bodies built before they were recorded, or whose heel could not be
  // bisected.
  std::optional<ScannedHeel> heel;
};

// Reads `source` (body.json's "source" object). A body built without --anatomy, or one whose
// record carries no anatomy, gives kNone. Throws InputError naming `file` when the record
// names an unknown anatomy or a landmark is malformed.
RecordedAnatomy ReadRecordedAnatomy(const Json& source, const std::string& file);

}  // namespace ergo
