#pragma once
// An imported avatar's face, made to answer gestura's face channels: the visemes (sil PP FF TH DD
// kk CH SS nn RR aa E ih oh ou) and the expression morphs (browInnerUp_L … tongueOut) that the
// face layer writes into clips (body/face_morphs.hpp names them). For every channel a morph target
// of that name is added to the mesh, made as a weighted sum of what the avatar has, in this order:
//   1. a morph already called like the channel (gestura's own export);
//   2. ARKit-style blend shapes (eyeBlinkLeft, jawOpen, mouthSmileLeft, browInnerUp …, matched
//      ignoring case and a "blendShape1."-style prefix); visemes are mixed from the mouth shapes;
//   3. VRM expressions (aa ih ou E oh, blink, eyeBlink_L/R, joy, anger, sadness, surprise).
// What cannot be made is listed, so the caller can say what this avatar will not show.
#include <map>
#include <string>
#include <vector>

#include "gestura/body/mesh.hpp"
#include "gestura/io/vrm.hpp"

namespace gestura {

struct FaceChannelReport {
  std::vector<std::string> mapped;   // channels the avatar now has, with where each came from
  std::vector<std::string> missing;  // channels it cannot show
  int from_own = 0, from_arkit = 0, from_expressions = 0;
};

// Adds the channel morphs to `mesh` (existing morphs are kept). `expressions` are the VRM
// expressions as read by read_vrm (our channel name → binds into mesh.morphs).
FaceChannelReport map_face_channels(Mesh& mesh, const std::map<std::string, std::vector<VrmMorphBind>>& expressions);

}  // namespace gestura
