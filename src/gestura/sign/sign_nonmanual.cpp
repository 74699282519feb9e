#include "gestura/sign/sign_nonmanual.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "gestura/anim/sampler.hpp"
#include "gestura/core/error.hpp"
#include "gestura/face/eye_aim.hpp"
#include "gestura/face/face_channels.hpp"
#include "gestura/face/jaw_motion.hpp"
#include "gestura/face/sampa.hpp"
#include "gestura/face/viseme_track.hpp"

namespace gestura {
namespace {

using face::HeadAxis;
namespace fc = face;

constexpr std::string_view kLeftEye = "l_eyeball_joint", kRightEye = "r_eyeball_joint";
constexpr std::string_view kLeftClavicle = "l_sternoclavicular", kRightClavicle = "r_sternoclavicular";
constexpr float kBlinkSeconds = 0.15f;
// Seconds per unit of relative phoneme duration (phoneme.hpp: a lax vowel is 1) when a mouth
// picture is spoken: about 6–7 phonemes a second, as JASigning speaks them; slower than speech,
// as mouthing with a sign is.
constexpr float kMouthingSecondsPerUnit = 0.15f;

// ---- the tables ------------------------------------------------------------------------------

// Eye directions in degrees: x + looks down, y + looks to the avatar's (signer's) left.
struct Gaze {
  std::string_view tag;
  float down, left;
};
constexpr std::array kGazeDirections{
    Gaze{"AD", 0, 0},   Gaze{"FR", 0, 0},    Gaze{"NO", 0, 0},    Gaze{"UP", -15, 0},  Gaze{"DN", 20, 0},
    Gaze{"LE", 0, 25},  Gaze{"RI", 0, -25},  Gaze{"LU", -12, 20}, Gaze{"UL", -12, 20}, Gaze{"LD", 15, 20},
    Gaze{"DL", 15, 20}, Gaze{"RU", -12, -20}, Gaze{"UR", -12, -20}, Gaze{"RD", 15, -20}, Gaze{"DR", 15, -20},
};

struct Shape {
  std::string_view channel;
  float weight = 0.0f;
};

// A mouth gesture: what it sounds like (SAMPA, stretched over the span like a mouth picture) and/or
// a shape held over the span (or made `repeats` times).
struct MouthGesture {
  std::string_view code;
  std::string_view sampa;
  std::array<Shape, 3> shapes{};
  int repeats = 1;
};

using fc::kCheekPuff, fc::kJawOpen, fc::kMouthPucker, fc::kMouthPress, fc::kTongueOut;
constexpr std::string_view kSmile[2] = {fc::kMouthSmileL, fc::kMouthSmileR};
constexpr std::string_view kFrown[2] = {fc::kMouthFrownL, fc::kMouthFrownR};

// HamNoSys mouth gestures by their descriptions (teeth D, jaw J, lips L, cheeks C, tongue T). Where
// the avatar lacks the exact shape (one-sided puffs, sucked-in cheeks, a raised upper lip) the
// nearest one it has stands in.
constexpr std::array kMouthGestures{
    MouthGesture{"D01", "i:s"},                                                    // eee-sss
    MouthGesture{"D02", "f"},                                                      // f
    MouthGesture{"D03", "Ef"},                                                     // ef
    MouthGesture{"D04", "af"},                                                     // af
    MouthGesture{"D05", "", {Shape{kJawOpen, 0.15f}}, 6},                          // clattering teeth
    MouthGesture{"D06", "", {Shape{kJawOpen, 0.12f}, Shape{kSmile[0], 0.3f}, Shape{kSmile[1], 0.3f}}, 5},
    MouthGesture{"D07", "Am"},                                                     // one bite, teeth closed
    MouthGesture{"D08", "", {Shape{kJawOpen, 0.3f}, Shape{kSmile[0], 0.7f}, Shape{kSmile[1], 0.7f}}},
    MouthGesture{"D09", "taI"},                                                    // teeth on lower lip, open
    MouthGesture{"J02", "", {Shape{kJawOpen, 0.2f}, Shape{kMouthPress, 0.5f}}, 4},   // chewing, mouth closed
    MouthGesture{"J03", "", {Shape{kJawOpen, 0.3f}, Shape{kSmile[0], 0.3f}, Shape{kSmile[1], 0.3f}}},
    MouthGesture{"J04", "gagaga"},
    MouthGesture{"L01", "S"},         MouthGesture{"L02", "prrr"},  MouthGesture{"L03", "pr"},
    MouthGesture{"L04", "", {Shape{kMouthPucker, 0.8f}, Shape{kMouthPress, 0.3f}}},  // pursed lips
    MouthGesture{"L05", "O"},         MouthGesture{"L06", "u:"},    MouthGesture{"L07", "oA"},
    MouthGesture{"L08", "boAm"},      MouthGesture{"L09", "bam"},   MouthGesture{"L10", "boA"},
    MouthGesture{"L11", "ba"},        MouthGesture{"L12", "bi:"},   MouthGesture{"L13", "pi"},
    MouthGesture{"L14", "pC"},        MouthGesture{"L15", "bs"},    MouthGesture{"L16", "pf"},
    MouthGesture{"L17", "p"},         MouthGesture{"L18", "p@p@p"},
    MouthGesture{"L19", "", {Shape{kCheekPuff, 0.6f}, Shape{kMouthPucker, 0.5f}}},   // phh
    MouthGesture{"L20", "", {Shape{kCheekPuff, 0.8f}, Shape{kMouthPucker, 0.3f}}},   // phh
    MouthGesture{"L21", "p", {Shape{kCheekPuff, 0.5f}}},                             // ph
    MouthGesture{"L22", "p", {Shape{kCheekPuff, 0.9f}}},                             // ph
    MouthGesture{"L23", "m"},
    MouthGesture{"L24", "m", {Shape{kCheekPuff, 0.5f}}},                             // mmm holding breath
    MouthGesture{"L25", "m@m@m"},
    MouthGesture{"L26", "", {Shape{kSmile[1], 0.5f}}},                               // one side of upper lip up
    MouthGesture{"L27", "", {Shape{kTongueOut, 0.4f}, Shape{kJawOpen, 0.15f}}},      // tongue to upper lip
    MouthGesture{"L28", "", {Shape{kTongueOut, 0.5f}, Shape{kJawOpen, 0.2f}}},
    MouthGesture{"L29", "", {Shape{kFrown[0], 0.7f}, Shape{kFrown[1], 0.7f}, Shape{kMouthPress, 0.5f}}},
    MouthGesture{"L30", "", {Shape{kFrown[0], 0.6f}, Shape{kFrown[1], 0.6f}, Shape{kMouthPucker, 0.6f}}},
    MouthGesture{"L31", "", {Shape{kFrown[0], 0.7f}, Shape{kFrown[1], 0.7f}, Shape{kMouthPress, 0.5f}}},
    MouthGesture{"L32", "", {Shape{kCheekPuff, 0.5f}, Shape{fc::kPP, 0.6f}}, 4},     // lips vibrate
    MouthGesture{"L33", "AS"},
    MouthGesture{"L34", "", {Shape{kSmile[0], 0.6f}, Shape{kSmile[1], 0.6f}, Shape{kMouthPress, 0.6f}}},
    MouthGesture{"L35", "", {Shape{kMouthPucker, 0.5f}, Shape{kCheekPuff, 0.4f}, Shape{kJawOpen, 0.05f}}},
    MouthGesture{"C01", "", {Shape{kCheekPuff, 1.0f}}},                              // puffed cheeks
    MouthGesture{"C02", "", {Shape{kCheekPuff, 1.0f}, Shape{kMouthPucker, 0.3f}}},
    MouthGesture{"C04", "", {Shape{kCheekPuff, 0.6f}}},                              // one cheek puffed
    MouthGesture{"C05", "", {Shape{kCheekPuff, 0.6f}, Shape{kMouthPucker, 0.3f}}},
    MouthGesture{"C06", "", {Shape{kCheekPuff, 0.6f}, Shape{kMouthPucker, 0.3f}}},
    MouthGesture{"C07", "", {Shape{kMouthPucker, 0.6f}, Shape{kJawOpen, 0.1f}}},     // cheeks sucked in
    MouthGesture{"C08", "u:", {Shape{kMouthPucker, 0.6f}}},
    MouthGesture{"C11", "", {Shape{kCheekPuff, 0.6f}}, 4},
    MouthGesture{"C12", "", {Shape{kMouthPress, 0.5f}, Shape{kMouthPucker, 0.2f}}},
    MouthGesture{"C13", "", {Shape{kJawOpen, 0.2f}, Shape{kCheekPuff, 0.3f}}, 3},
    MouthGesture{"T01", "l"},
    MouthGesture{"T02", "l", {Shape{kTongueOut, 0.3f}}},
    MouthGesture{"T03", "l@l@l"},
    MouthGesture{"T04", "", {Shape{kTongueOut, 0.6f}, Shape{kJawOpen, 0.3f}}},
    MouthGesture{"T05", "a", {Shape{kTongueOut, 0.5f}}},
    MouthGesture{"T06", "", {Shape{kTongueOut, 0.6f}, Shape{kJawOpen, 0.3f}}, 4},
    MouthGesture{"T07", "lalala"},    MouthGesture{"T08", "alalal"}, MouthGesture{"T09", "als"},
    MouthGesture{"T10", "lf"},        MouthGesture{"T11", "laf"},
    MouthGesture{"T13", "", {Shape{kTongueOut, 0.5f}, Shape{kCheekPuff, 0.3f}, Shape{kJawOpen, 0.2f}}},
    MouthGesture{"T14", "", {Shape{kTongueOut, 0.6f}, Shape{kJawOpen, 0.3f}}},
    MouthGesture{"T16", "", {Shape{kMouthPucker, 0.8f}, Shape{kTongueOut, 0.6f}}},
    MouthGesture{"T17", "", {Shape{kTongueOut, 0.6f}, Shape{kJawOpen, 0.4f}}, 1},
};

// Mouth gestures of the HamNoSys list that need a shape no morph gives (the tongue inside the
// cheek or circling): known, but not performed.
constexpr std::array<std::string_view, 4> kUnshapedMouthGestures{"C09", "C10", "T12", "T15"};

const MouthGesture* find_mouth_gesture(std::string_view code) {
  for (const MouthGesture& g : kMouthGestures)
    if (g.code == code) return &g;
  return nullptr;
}

// ---- planning ----------------------------------------------------------------------------------

class TierPlanner {
 public:
  TierPlanner(SignNonManualActions& out, float start, float end) : out_(out), sign_start_(start), sign_end_(end) {}

  // The part of the sign the next value spans (NonManual::from, to).
  void select(const sign::NonManual& nm) {
    const float from = std::clamp(std::isfinite(nm.from) ? nm.from : 0.0f, 0.0f, 1.0f);
    const float to = std::clamp(std::isfinite(nm.to) ? nm.to : 1.0f, from, 1.0f);
    start_ = sign_start_ + from * (sign_end_ - sign_start_);
    end_ = sign_start_ + to * (sign_end_ - sign_start_);
  }

  // Performs one value; false when it is not one this tier knows.
  bool perform(const sign::NonManual& nm) {
    using T = sign::NonManualTier;
    const std::string_view v = nm.value;
    switch (nm.tier) {
      case T::shoulder: return shoulder(v);
      case T::body: return body(v);
      case T::head: return head(v);
      case T::eye_gaze: return eye_gaze(v);
      case T::eyebrows: return eyebrows(v);
      case T::eyelids: return eyelids(v);
      case T::nose: return nose(v);
      case T::cheeks: return v.starts_with("C") && mouth_gesture(nm);
      case T::mouth_gesture: return mouth_gesture(nm);
      case T::mouth_picture: return mouth_picture(nm);
      case T::extra: return false;
    }
    return false;
  }

  // The head turned with the eyes (LI), once every gaze is known: by half a fixed direction, and
  // along with every gaze at the hands.
  bool head_with_gaze() {
    for (HandGaze& g : out_.gaze) g.with_head = true;
    if (gaze_) {
      add_head(HeadAxis::pitch, 0.5f * gaze_->down);
      add_head(HeadAxis::yaw, 0.5f * gaze_->left);
    }
    return gaze_ || !out_.gaze.empty();
  }

 private:
  SignNonManualActions& out_;
  float sign_start_, sign_end_;
  float start_ = 0.0f, end_ = 0.0f;  // of the value being performed
  std::optional<Gaze> gaze_;  // the fixed eye direction, when the sign has one

  float span() const { return end_ - start_; }

  void morph(std::string_view channel, float peak) { out_.face.push_back(fc::make_action(channel, start_, end_, peak)); }
  void morph_pair(std::string_view left, std::string_view right, float peak, bool l = true, bool r = true) {
    if (l) morph(left, peak);
    if (r) morph(right, peak);
  }
  // `n` bumps of the shape, one after another over the span.
  void repeated(std::string_view channel, float peak, int n) {
    const float each = span() / static_cast<float>(n);
    for (int k = 0; k < n; ++k) {
      const float s = start_ + each * static_cast<float>(k);
      out_.face.push_back(fc::FaceAction{channel, s, s + each, peak, 0.5f * each, 0.5f * each});
    }
  }
  void add_head(HeadAxis axis, float degrees, float frequency = 0.0f) {
    out_.head.push_back(fc::HeadAction{axis, start_, end_, deg(degrees), frequency});
  }
  void joint(std::string_view name, vec3 degrees, float frequency = 0.0f) {
    out_.joints.push_back(fc::make_offset(name, glm::radians(degrees), start_, end_, frequency));
  }
  // Up and back down once over the span.
  void joint_bump(std::string_view name, vec3 degrees) {
    out_.joints.push_back(fc::JointOffset{name, glm::radians(degrees), start_, end_, 0.5f * span(), 0.5f * span()});
  }
  void clavicles(bool left, bool right, float raise, float forward, bool bump = false) {
    // Left clavicle: + z raises it, − y brings the shoulder forward; the right one mirrors. The
    // arm keeps its direction (it rises with the shoulder instead of swinging out with the clavicle).
    const vec3 l(0.0f, -forward, raise), r(0.0f, forward, -raise);
    if (left) bump ? joint_bump(kLeftClavicle, l) : joint(kLeftClavicle, l);
    if (left) out_.joints.back().children_keep_orientation = true;
    if (right) bump ? joint_bump(kRightClavicle, r) : joint(kRightClavicle, r);
    if (right) out_.joints.back().children_keep_orientation = true;
  }
  // Spread a bend of the trunk over the lumbar and thoracic joints (x forward, y to the left, z to the right).
  void spine(vec3 degrees, bool bump = false, float frequency = 0.0f) {
    constexpr std::array<std::pair<std::string_view, float>, 4> kShare{
        {{"vl3", 0.2f}, {"vt12", 0.3f}, {"vt6", 0.3f}, {"vt1", 0.2f}}};
    for (const auto& [name, share] : kShare) {
      if (bump) joint_bump(name, degrees * share);
      else joint(name, degrees * share, frequency);
    }
  }

  bool shoulder(std::string_view v) {
    if (v.size() != 2) return false;
    const char side = v[1];
    if (side != 'L' && side != 'R' && side != 'B') return false;
    const bool l = side != 'R', r = side != 'L';
    switch (v[0]) {
      case 'U': clavicles(l, r, 12.0f, 0.0f); return true;
      case 'H': clavicles(l, r, 3.0f, 15.0f); return true;
      case 'S': clavicles(l, r, 15.0f, 0.0f, true); return true;
      default: return false;
    }
  }

  bool body(std::string_view v) {
    if (v == "RL") spine({0, 16, 0});
    else if (v == "RR") spine({0, -16, 0});
    else if (v == "TL") spine({0, 0, -10});
    else if (v == "TR") spine({0, 0, 10});
    else if (v == "TF") spine({12, 0, 0});
    else if (v == "TB") spine({-8, 0, 0});
    else if (v == "ST") spine({-4, 0, 0});
    else if (v == "RD") spine({10, 0, 0}), clavicles(true, true, 0.0f, 8.0f);
    else if (v == "SI") spine({-6, 0, 0}, true), clavicles(true, true, 8.0f, 0.0f, true);
    else if (v == "HE") spine({-4, 0, 0}, false, 1.2f), clavicles(true, true, 6.0f, 0.0f);
    else return false;
    return true;
  }

  bool head(std::string_view v) {
    // Head angles: pitch + forward, yaw + to the signer's left, roll + top of the head to the right.
    if (v == "NO") add_head(HeadAxis::pitch, 10.0f, 2.0f);
    else if (v == "SH") add_head(HeadAxis::yaw, 10.0f, 2.5f);
    else if (v == "SL") add_head(HeadAxis::yaw, 20.0f);
    else if (v == "SR") add_head(HeadAxis::yaw, -20.0f);
    else if (v == "TL") add_head(HeadAxis::roll, -12.0f);
    else if (v == "TR") add_head(HeadAxis::roll, 12.0f);
    else if (v == "NF") add_head(HeadAxis::pitch, 12.0f);
    else if (v == "NB") add_head(HeadAxis::pitch, -12.0f);
    // Pushed: the neck bends one way and the head the other, so the face moves but stays level.
    else if (v == "PF") joint("vc7", {12, 0, 0}), joint("skullbase", {-12, 0, 0});
    else if (v == "PB") joint("vc7", {-8, 0, 0}), joint("skullbase", {8, 0, 0});
    else return false;
    return true;
  }

  bool eye_gaze(std::string_view v) {
    if (v == "HD" || v == "HI" || v == "HC") {
      out_.gaze.push_back(HandGaze{v == "HC" ? Hand::Left : Hand::Right, start_, end_, v == "HD"});
      return true;
    }
    if (v == "RO") {  // rolling: up, and across from one side to the other once
      if (span() <= 0.0f) return true;
      joint(kLeftEye, {-15, 0, 0}), joint(kRightEye, {-15, 0, 0});
      joint(kLeftEye, {0, 20, 0}, 1.0f / span()), joint(kRightEye, {0, 20, 0}, 1.0f / span());
      return true;
    }
    for (const Gaze& g : kGazeDirections) {
      if (g.tag != v) continue;
      gaze_ = g;
      if (g.down != 0.0f || g.left != 0.0f) {
        joint(kLeftEye, {g.down, g.left, 0});
        joint(kRightEye, {g.down, g.left, 0});
      }
      return true;
    }
    return false;
  }

  bool eyebrows(std::string_view v) {
    const bool l = v != "RR", r = v != "RL";
    if (v == "RB" || v == "RL" || v == "RR") {
      morph_pair(fc::kBrowInnerUpL, fc::kBrowInnerUpR, 0.8f, l, r);
      morph_pair(fc::kBrowOuterUpL, fc::kBrowOuterUpR, 0.8f, l, r);
    } else if (v == "FU") {
      morph_pair(fc::kBrowDownL, fc::kBrowDownR, 0.8f);
    } else {
      return false;
    }
    return true;
  }

  bool eyelids(std::string_view v) {
    if (v == "BB") {  // one blink at the end of the sign
      const float s = std::max(start_, end_ - kBlinkSeconds);
      for (std::string_view c : {fc::kEyeBlinkL, fc::kEyeBlinkR})
        out_.face.push_back(fc::FaceAction{c, s, end_, 1.0f, 0.5f * (end_ - s), 0.5f * (end_ - s)});
      return true;
    }
    if (v.size() != 2) return false;
    const char side = v[1];
    if (side != 'L' && side != 'R' && side != 'B') return false;
    const bool l = side != 'R', r = side != 'L';
    switch (v[0]) {
      case 'W': morph_pair(fc::kEyeWideL, fc::kEyeWideR, 0.8f, l, r); return true;
      case 'S': morph_pair(fc::kEyeSquintL, fc::kEyeSquintR, 0.6f, l, r); return true;
      case 'C': morph_pair(fc::kEyeBlinkL, fc::kEyeBlinkR, 1.0f, l, r); return true;
      case 'T':
        morph_pair(fc::kEyeBlinkL, fc::kEyeBlinkR, 1.0f, l, r);
        morph_pair(fc::kEyeSquintL, fc::kEyeSquintR, 0.7f, l, r);
        return true;
      default: return false;
    }
  }

  bool nose(std::string_view v) {
    if (v != "WR") return false;
    morph_pair(fc::kBrowDownL, fc::kBrowDownR, 0.4f);
    morph_pair(fc::kEyeSquintL, fc::kEyeSquintR, 0.5f);
    return true;
  }

  void sampa(const sign::NonManual& nm, std::string_view text) {
    const fc::SampaReading reading = fc::phonemes_from_sampa(text);
    if (!reading.unknown.empty())
      out_.warnings.push_back({nm.line, std::string(sign::nonmanual_tier_name(nm.tier)) + " '" + nm.value +
                                            "': '" + reading.unknown + "' is not SAMPA; skipped"});
    // At most a natural mouthing rate: a long sign does not drag its word out.
    float units = 0.0f;
    for (const fc::Phoneme& p : reading.phonemes) units += p.duration;
    const float end = std::min(end_, start_ + units * kMouthingSecondsPerUnit);
    fc::append_viseme_actions(reading.phonemes, start_, end, 1.0f, out_.face);
  }

  bool mouth_gesture(const sign::NonManual& nm) {
    const std::string_view v = nm.value;
    if (v == "J01") {  // the lower jaw moves sideways, left and right
      joint("temporomandibular", {0, 6, 0}, 2.0f);
      return true;
    }
    if (v == "C03") {  // cheeks puffed gradually: a slow rise over most of the sign
      out_.face.push_back(fc::FaceAction{kCheekPuff, start_, end_, 1.0f, 0.8f * span(), 0.1f * span()});
      return true;
    }
    const MouthGesture* g = find_mouth_gesture(v);
    if (!g) return false;
    if (!g->sampa.empty()) sampa(nm, g->sampa);
    for (const Shape& s : g->shapes) {
      if (s.channel.empty()) continue;
      if (g->repeats > 1) repeated(s.channel, s.weight, g->repeats);
      else morph(s.channel, s.weight);
    }
    return true;
  }

  bool mouth_picture(const sign::NonManual& nm) {
    sampa(nm, nm.value);
    return true;
  }
};

std::string known_values(sign::NonManualTier tier) {
  using T = sign::NonManualTier;
  switch (tier) {
    case T::shoulder: return "UL UR UB HL HR HB SL SR SB";
    case T::body: return "RL RR TL TR TF TB SI HE ST RD";
    case T::head: return "NO SH SL SR TL TR NF NB PF PB LI";
    case T::eye_gaze: return "AD FR NO UP DN LE RI LU LD RU RD HD HI HC RO";
    case T::eyebrows: return "RB RL RR FU";
    case T::eyelids: return "WB WL WR SB SL SR CB CL CR TB TL TR BB";
    case T::nose: return "WR TW WI";
    case T::cheeks: return "C01–C13";
    case T::mouth_gesture: return "D01–D09 J01–J04 L01–L35 C01–C13 T01–T17";
    case T::mouth_picture: return "SAMPA";
    case T::extra: return "none: extra movements are not performed";
  }
  return "";
}

// A hand this far (metres) from its bind-pose place is taking part in the sign.
constexpr float kHandUpFromRest = 0.1f;

vec3 palm_centre(const SigningRig& rig, Hand hand, std::span<const mat4> model) {
  const HandRig& h = rig.hand(hand);
  return vec3(model[joint_slot(h.wrist)] * vec4(h.palm_centre_local, 1.0f));
}

}  // namespace

SignNonManualActions plan_sign_nonmanuals(std::span<const sign::NonManual> tiers, float start, float end) {
  if (!std::isfinite(start) || !std::isfinite(end) || end < start || end - start > 3600.0f)
    throw Error("non-manuals: the sign's span [" + std::to_string(start) + ", " + std::to_string(end) +
                "] s is not finite, reversed or longer than an hour");
  SignNonManualActions out;
  if (end <= start) return out;
  TierPlanner planner(out, start, end);
  std::vector<const sign::NonManual*> linked;  // LI waits for the gaze
  for (std::size_t i = 0; i < tiers.size(); ++i) {
    const sign::NonManual& nm = tiers[i];
    if (nm.value.empty()) continue;  // an empty tag (tools write tag="") asks for nothing
    ++out.values;
    // The same value again over the same time (generators repeat <hnm_head tag="SH"/> to insist):
    // one movement, not twice its amplitude.
    const auto same = [&](const sign::NonManual& o) {
      return o.tier == nm.tier && o.value == nm.value && o.from == nm.from && o.to == nm.to;
    };
    if (std::any_of(tiers.begin(), tiers.begin() + static_cast<std::ptrdiff_t>(i), same)) {
      ++out.mapped;
      continue;
    }
    planner.select(nm);
    if (nm.tier == sign::NonManualTier::head && nm.value == "LI") {
      linked.push_back(&nm);
      continue;
    }
    const bool mouth = nm.tier == sign::NonManualTier::mouth_gesture || nm.tier == sign::NonManualTier::cheeks;
    const bool unshaped = mouth ? std::find(kUnshapedMouthGestures.begin(), kUnshapedMouthGestures.end(), nm.value) !=
                                      kUnshapedMouthGestures.end()
                                : nm.tier == sign::NonManualTier::nose && (nm.value == "TW" || nm.value == "WI");
    if (planner.perform(nm)) {
      ++out.mapped;
    } else if (unshaped) {
      out.warnings.push_back({nm.line, std::string(sign::nonmanual_tier_name(nm.tier)) + " '" + nm.value + "' needs a " +
                                           (mouth ? "tongue" : "nostril") + " shape the avatar does not have; not performed"});
    } else {
      out.warnings.push_back({nm.line, "unknown " + std::string(sign::nonmanual_tier_name(nm.tier)) + " value '" +
                                           nm.value.substr(0, 40) + "' (known: " + known_values(nm.tier) +
                                           "); not performed"});
    }
  }
  for (const sign::NonManual* nm : linked) {
    planner.select(*nm);
    if (planner.head_with_gaze()) ++out.mapped;
    else out.warnings.push_back({nm->line, "head 'LI' (head turned with the eyes) needs an eye gaze "
                                           "(UP, DN, LE, ..., HI, HC, HD) in the sign; not performed"});
  }
  return out;
}

bool write_hand_gaze(std::span<const HandGaze> gaze, const SigningRig& rig, float fps, Clip& clip) {
  const Skeleton& s = rig.skeleton();
  if (s.find(kLeftEye) < 0 || s.find(kRightEye) < 0) return false;
  if (gaze.empty()) return true;
  if (!(fps >= 1.0f && fps <= 240.0f)) throw Error("hand gaze: fps must be between 1 and 240");

  // Keys at every ramp step and every frame of each span.
  std::vector<fc::FaceAction> envelopes;
  std::vector<float> times;
  for (const HandGaze& g : gaze) {
    if (!std::isfinite(g.start) || !std::isfinite(g.end) || g.end < g.start || g.end - g.start > 3600.0f)
      throw Error("hand gaze: non-finite, reversed or over-long span");
    envelopes.push_back(fc::make_action("", g.start, g.end, 1.0f));
    const fc::FaceAction& e = envelopes.back();
    for (int k = 0; k <= 8; ++k) {
      times.push_back(g.start + e.ramp_in * static_cast<float>(k) / 8.0f);
      times.push_back(g.end - e.ramp_out * static_cast<float>(k) / 8.0f);
    }
    for (float t = g.start; t < g.end; t += 1.0f / fps) times.push_back(t);
  }
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end(), [](float x, float y) { return y - x < 1e-4f; }), times.end());

  // Where overlapping spans hand over, the target moves between theirs by their weights.
  fc::write_gaze(s, times, [&](float t, std::span<const mat4> model) {
    vec3 target(0.0f);
    float weight = 0.0f, head = 0.0f;
    for (std::size_t g = 0; g < gaze.size(); ++g) {
      const float w = fc::action_weight(envelopes[g], t);
      if (w <= 0.0f) continue;
      vec3 point = palm_centre(rig, gaze[g].hand, model);
      if (gaze[g].both_hands) {
        const Hand other = gaze[g].hand == Hand::Right ? Hand::Left : Hand::Right;
        const vec3 other_palm = palm_centre(rig, other, model);
        if (glm::distance(other_palm, palm_centre(rig, other, rig.bind_model)) > kHandUpFromRest)
          point = 0.5f * (point + other_palm);
      }
      target += w * point;
      weight += w;
      head += gaze[g].with_head ? w : 0.0f;
    }
    return weight > 0.0f ? fc::GazeTarget{target / weight, weight, head} : fc::GazeTarget{};
  }, clip);
  return true;
}

std::vector<NonManualWarning> add_sign_nonmanuals(std::span<const sign::NonManual> tiers, float start, float end,
                                                  const SigningRig& rig, float fps, Clip& clip) {
  SignNonManualActions actions = plan_sign_nonmanuals(tiers, start, end);
  std::vector<NonManualWarning> warnings = std::move(actions.warnings);
  const Skeleton& s = rig.skeleton();
  const int first_line = tiers.empty() ? 0 : tiers.front().line;
  if (!actions.face.empty()) fc::write_face_channels(actions.face, clip);
  const bool has_head = s.find("vc4") >= 0 && s.find("skullbase") >= 0;
  const bool head_with_hands = std::any_of(actions.gaze.begin(), actions.gaze.end(), [](const HandGaze& g) { return g.with_head; });
  if (!has_head && (!actions.head.empty() || head_with_hands)) {
    warnings.push_back({first_line, "the avatar has no vc4/skullbase joints: head movements not performed"});
    for (HandGaze& g : actions.gaze) g.with_head = false;
  }
  if (!actions.head.empty() && has_head) fc::write_head_rotations(actions.head, s, clip);
  fc::write_jaw_from_channel(s, clip);
  if (!write_hand_gaze(actions.gaze, rig, fps, clip))
    warnings.push_back({first_line, "the avatar has no eyeball joints: eye gaze not performed"});
  for (std::string_view joint : fc::add_joint_offsets(actions.joints, s, clip))
    warnings.push_back({first_line, "the avatar has no joint '" + std::string(joint) + "': its non-manual part is not performed"});
  return warnings;
}

}  // namespace gestura
