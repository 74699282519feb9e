#include "gestura/sign/phonology_handshape.hpp"

#include <cmath>
#include <cstdio>

#include "gestura/core/math.hpp"

namespace gestura {

namespace {

// Tables are written in degrees (what anatomy texts and goniometers use) and converted once.
constexpr FingerFlexion flex(float mcp, float pip, float dip) { return {deg(mcp), deg(pip), deg(dip)}; }
constexpr ThumbPose thumb(float cmc_flexion, float cmc_abduction, float cmc_opposition, float mcp, float ip) {
  return {deg(cmc_flexion), deg(cmc_abduction), deg(cmc_opposition), deg(mcp), deg(ip)};
}
constexpr std::array<float, 4> spread(float index, float middle, float ring, float pinky) {
  return {deg(index), deg(middle), deg(ring), deg(pinky)};
}

// Finger curled into the palm. The cascade (index a little less flexed at the MCP than the pinky)
// is how a relaxed fist looks: the ulnar metacarpals are more mobile (CMC 4/5), so the ring and
// little fingers sit deeper. PIP ~100° and DIP ~55° bring the pads onto the palm, not the nails.
constexpr FingerFlexion kCurled[4] = {flex(82, 100, 55), flex(86, 100, 55), flex(88, 100, 55), flex(90, 100, 55)};
constexpr FingerFlexion kStraight = flex(0, 0, 0);

// Thumb poses shared by several shapes.
// Alongside: resting against the radial side of the index (ASL A, the HamNoSys flat hand), its tip
// ~2 cm from the palm plane (at 0° abduction the avatar's thumb stands 4–6 cm out of it, which held
// a flat palm 5–10 cm off the chest it should touch).
constexpr ThumbPose kThumbAlongside = thumb(0, -15, 0, 8, 5);
// Alongside a fist (ASL A, the HamNoSys fist): the curled index stands ~4 cm in front of the palm,
// so the thumb comes forward with it (radial extension, MCP and IP bent) and lies against the
// index's side, its tip level with the top of the fist (~2.5 cm above the index knuckle). The flat
// hand's thumb held straight up there stood 4 cm above the knuckles: a thumbs-up, not an A.
constexpr ThumbPose kThumbAlongsideFist = thumb(-20, -5, 0, 40, 20);
// Across: metacarpal swung toward the little finger and pronated so the pad lies over the middle
// phalanges of the curled index/middle (ASL 1, U, the HamNoSys thumb-across modifier). On the
// avatar it runs low, across the fingertips, and its tip stands 1 cm past the little finger.
constexpr ThumbPose kThumbAcross = thumb(40, 22, 42, 32, 22);
// Across the fist of ASL S as a signer makes it: less CMC flexion, the phalanges bent over the
// fingers, the pad on the middle phalanges of the index and middle fingers, the tip at the middle or
// ring finger. Only S takes it so far: given to every thumb-across shape, it left 5 more of the
// 4,070 signs of the lexicon sweep turned over 25° (236, ratchet 231): the planner's hand points
// include the thumb tip, and the sign layer has yet to be measured with it.
constexpr ThumbPose kThumbAcrossFist = thumb(10, 25, 30, 50, 35);
// Across the palm under straight fingers (ASL B, 4): more CMC flexion, less abduction, since the
// thumb must fit between the palm and the extended fingers.
constexpr ThumbPose kThumbInPalm = thumb(45, 10, 40, 40, 20);
// Out: radial abduction in the palm plane to ~40° with all joints straight (ASL L, Y, 5).
constexpr ThumbPose kThumbOut = thumb(-40, 15, 0, 0, 0);
// Opposed: palmar abduction plus pronation so the pad faces the finger pads (no contact).
constexpr ThumbPose kThumbOpposed = thumb(10, 55, 50, 10, 10);

HandPosture with(ThumbPose t, FingerFlexion i, FingerFlexion m, FingerFlexion r, FingerFlexion p,
                 std::array<float, 4> s = {}, FingerSet contacts = 0) {
  HandPosture h;
  h.thumb = t;
  h.fingers = {i, m, r, p};
  h.spread = s;
  h.thumb_tip_contacts = contacts;
  return h;
}

bool inside(float v, JointRange r) { return std::isfinite(v) && v >= r.min - 1e-6f && v <= r.max + 1e-6f; }

std::string describe(const char* what, float v, JointRange r) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "%s %.3f rad outside [%.3f, %.3f]", what, static_cast<double>(v),
                static_cast<double>(r.min), static_cast<double>(r.max));
  return buf;
}

struct Named {
  std::string_view ours;
  std::string_view hamnosys;
};

constexpr Named kBasicNames[kBasicHandshapeCount] = {
    {"fist", "hamfist"},
    {"flat", "hamflathand"},
    {"finger2", "hamfinger2"},
    {"finger23", "hamfinger23"},
    {"finger23spread", "hamfinger23spread"},
    {"finger2345", "hamfinger2345"},
    {"pinch12", "hampinch12"},
    {"pinchall", "hampinchall"},
    {"pinch12open", "hampinch12open"},
    {"cee12", "hamcee12"},
    {"ceeall", "hamceeall"},
    {"cee12open", "hamceeopen"},  // HamNoSys 4 calls the wide C "ceeopen"
};
constexpr Named kThumbNames[4] = {
    {"default", ""}, {"out", "hamthumboutmod"}, {"across", "hamthumbacrossmod"}, {"opposed", "hamthumbopenmod"}};
constexpr Named kBendingNames[kFingerBendingCount] = {
    {"bent", "hamfingerstraightmod"}, {"round", "hamfingerbendmod"},  {"hooked", "hamfingerhookmod"},
    {"dblbent", "hamdoublebent"},     {"dblhooked", "hamdoublehooked"}, {"halfbent", ""}};
constexpr std::string_view kAslNames[kAslHandshapeCount] = {
    "A", "B", "C", "D", "E", "F", "G", "I", "K", "L", "M", "N", "O", "R",
    "S", "T", "U", "V", "W", "X", "Y", "1", "3", "4", "5", "6", "7", "8"};

template <class Enum, std::size_t N>
std::optional<Enum> find_name(const Named (&table)[N], std::string_view name) {
  for (std::size_t k = 0; k < N; ++k)
    if (name == table[k].ours || (!table[k].hamnosys.empty() && name == table[k].hamnosys))
      return static_cast<Enum>(k);
  return std::nullopt;
}

}  // namespace

const FingerLimits kFingerLimits{{0.0f, deg(90)}, {0.0f, deg(110)}, {0.0f, deg(80)}, {deg(-20), deg(30)}};
const ThumbLimits kThumbLimits{{deg(-45), deg(50)}, {deg(-15), deg(70)}, {0.0f, deg(60)}, {0.0f, deg(60)}, {deg(-10), deg(80)}};

std::string anatomical_violation(const HandPosture& h) {
  static constexpr const char* kFingerNames[4] = {"index", "middle", "ring", "pinky"};
  for (std::size_t f = 0; f < 4; ++f) {
    const std::string name = kFingerNames[f];
    if (!inside(h.fingers[f].mcp, kFingerLimits.mcp)) return describe((name + " mcp").c_str(), h.fingers[f].mcp, kFingerLimits.mcp);
    if (!inside(h.fingers[f].pip, kFingerLimits.pip)) return describe((name + " pip").c_str(), h.fingers[f].pip, kFingerLimits.pip);
    if (!inside(h.fingers[f].dip, kFingerLimits.dip)) return describe((name + " dip").c_str(), h.fingers[f].dip, kFingerLimits.dip);
    if (!inside(h.spread[f], kFingerLimits.spread)) return describe((name + " spread").c_str(), h.spread[f], kFingerLimits.spread);
  }
  const ThumbPose& t = h.thumb;
  if (!inside(t.cmc_flexion, kThumbLimits.cmc_flexion)) return describe("thumb cmc flexion", t.cmc_flexion, kThumbLimits.cmc_flexion);
  if (!inside(t.cmc_abduction, kThumbLimits.cmc_abduction)) return describe("thumb cmc abduction", t.cmc_abduction, kThumbLimits.cmc_abduction);
  if (!inside(t.cmc_opposition, kThumbLimits.cmc_opposition)) return describe("thumb cmc opposition", t.cmc_opposition, kThumbLimits.cmc_opposition);
  if (!inside(t.mcp, kThumbLimits.mcp)) return describe("thumb mcp", t.mcp, kThumbLimits.mcp);
  if (!inside(t.ip, kThumbLimits.ip)) return describe("thumb ip", t.ip, kThumbLimits.ip);
  return {};
}

HandPosture mix(const HandPosture& a, const HandPosture& b, float s) {
  auto lerp = [s](float x, float y) { return x + (y - x) * s; };
  HandPosture out = s < 0.5f ? a : b;
  out.thumb = {lerp(a.thumb.cmc_flexion, b.thumb.cmc_flexion), lerp(a.thumb.cmc_abduction, b.thumb.cmc_abduction),
               lerp(a.thumb.cmc_opposition, b.thumb.cmc_opposition), lerp(a.thumb.mcp, b.thumb.mcp),
               lerp(a.thumb.ip, b.thumb.ip)};
  for (std::size_t f = 0; f < 4; ++f) {
    out.fingers[f] = {lerp(a.fingers[f].mcp, b.fingers[f].mcp), lerp(a.fingers[f].pip, b.fingers[f].pip),
                      lerp(a.fingers[f].dip, b.fingers[f].dip)};
    out.spread[f] = lerp(a.spread[f], b.spread[f]);
  }
  return out;
}

HandPosture basic_handshape(BasicHandshape shape) {
  const FingerFlexion* c = kCurled;
  switch (shape) {
    case BasicHandshape::Fist:
      return with(kThumbAlongsideFist, c[0], c[1], c[2], c[3]);
    case BasicHandshape::Flat:
      return with(kThumbAlongside, kStraight, kStraight, kStraight, kStraight);
    case BasicHandshape::Finger2:
      return with(kThumbAcross, kStraight, c[1], c[2], c[3]);
    case BasicHandshape::Finger23:
      return with(kThumbAcross, kStraight, kStraight, c[2], c[3]);
    case BasicHandshape::Finger23Spread:
      // V: index and middle each abducted ~12° from the midline → ~25° between them.
      return with(kThumbAcross, kStraight, kStraight, c[2], c[3], spread(12, 12, 0, 0));
    case BasicHandshape::Finger2345:
      // Open spread hand: pinky abducts most (it has the largest abduction range), middle least.
      return with(kThumbInPalm, kStraight, kStraight, kStraight, kStraight, spread(15, 0, 10, 22));
    case BasicHandshape::Pinch12:
      // Index round (45/55/25) so its pad meets the opposed thumb pad; the ring of thumb and index
      // is ~2 cm across on an adult hand. The other fingers stay extended and slightly fanned (F).
      return with(thumb(15, 45, 50, 20, 15), flex(45, 55, 25), kStraight, kStraight, kStraight,
                  spread(0, 3, 8, 15), finger_bit(Finger::Index));
    case BasicHandshape::PinchAll:
      // Flat-O / bunched hand: fingers bent mostly at the MCP with PIP/DIP modest, all tips gathered
      // on the thumb tip; the ulnar fingers converge (negative spread).
      return with(thumb(15, 50, 55, 15, 5), flex(50, 30, 15), flex(52, 30, 15), flex(55, 30, 15), flex(58, 30, 15),
                  spread(-5, 0, 5, 10), kAllFourFingers);
    case BasicHandshape::Pinch12Open:
      return with(thumb(10, 45, 45, 15, 10), flex(40, 45, 20), kStraight, kStraight, kStraight, spread(0, 3, 8, 15));
    case BasicHandshape::Cee12:
      // C of thumb and index ~4–5 cm open: less flexion than the pinch, thumb more abducted.
      return with(thumb(5, 50, 35, 10, 10), flex(30, 40, 20), kStraight, kStraight, kStraight, spread(0, 3, 8, 15));
    case BasicHandshape::CeeAll:
      return with(thumb(5, 50, 35, 10, 10), flex(30, 40, 20), flex(30, 40, 20), flex(30, 40, 20), flex(30, 40, 20));
    case BasicHandshape::Cee12Open:
      return with(thumb(0, 60, 25, 5, 0), flex(20, 25, 10), kStraight, kStraight, kStraight, spread(0, 3, 8, 15));
  }
  return {};
}

FingerSet selected_fingers(BasicHandshape shape) {
  switch (shape) {
    case BasicHandshape::Fist:
      return 0;
    case BasicHandshape::Finger2:
    case BasicHandshape::Pinch12:
    case BasicHandshape::Pinch12Open:
    case BasicHandshape::Cee12:
    case BasicHandshape::Cee12Open:
      return finger_bit(Finger::Index);
    case BasicHandshape::Finger23:
    case BasicHandshape::Finger23Spread:
      return finger_bit(Finger::Index) | finger_bit(Finger::Middle);
    case BasicHandshape::Flat:
    case BasicHandshape::Finger2345:
    case BasicHandshape::PinchAll:
    case BasicHandshape::CeeAll:
      return kAllFourFingers;
  }
  return 0;
}

FingerFlexion bending_flexion(FingerBending bending) {
  switch (bending) {
    case FingerBending::Bent:
      return flex(80, 5, 0);
    case FingerBending::Round:
      return flex(40, 50, 30);
    case FingerBending::Hooked:
      // PIP and DIP are coupled by the oblique retinacular ligament: DIP ≈ 2/3 of PIP.
      return flex(0, 90, 60);
    case FingerBending::DoubleBent:
      return flex(60, 90, 15);
    case FingerBending::DoubleHooked:
      return flex(15, 105, 75);
    case FingerBending::HalfBent:
      return flex(45, 0, 0);
  }
  return kStraight;
}

ThumbPose thumb_pose(ThumbModifier modifier, BasicHandshape shape) {
  switch (modifier) {
    case ThumbModifier::Default:
      return basic_handshape(shape).thumb;
    case ThumbModifier::Out:
      return kThumbOut;
    case ThumbModifier::Across:
      // Over straight fingers "across" means across the palm; over curled fingers, across them.
      return (shape == BasicHandshape::Flat || shape == BasicHandshape::Finger2345) ? kThumbInPalm : kThumbAcross;
    case ThumbModifier::Opposed:
      return kThumbOpposed;
  }
  return kThumbAlongside;
}

void apply_bending(HandPosture& posture, FingerSet fingers, FingerBending bending) {
  const FingerFlexion value = bending_flexion(bending);
  for (unsigned f = 1; f <= 4; ++f)
    if (fingers & (1u << f)) posture.fingers[f - 1] = value;
}

HandPosture make_handshape(BasicHandshape shape, ThumbModifier modifier, std::optional<FingerBending> bending) {
  HandPosture h = basic_handshape(shape);
  h.thumb = thumb_pose(modifier, shape);
  // A thumb moved away from its default no longer touches the fingertips.
  if (modifier != ThumbModifier::Default) h.thumb_tip_contacts = 0;
  if (bending) apply_bending(h, selected_fingers(shape), *bending);
  return h;
}

std::string_view to_string(BasicHandshape shape) { return kBasicNames[static_cast<std::size_t>(shape)].ours; }
std::optional<BasicHandshape> parse_basic_handshape(std::string_view name) {
  if (name == "ceeopen") return BasicHandshape::Cee12Open;
  return find_name<BasicHandshape>(kBasicNames, name);
}
std::string_view to_string(ThumbModifier modifier) { return kThumbNames[static_cast<std::size_t>(modifier)].ours; }
std::optional<ThumbModifier> parse_thumb_modifier(std::string_view name) { return find_name<ThumbModifier>(kThumbNames, name); }
std::string_view to_string(FingerBending bending) { return kBendingNames[static_cast<std::size_t>(bending)].ours; }
std::optional<FingerBending> parse_finger_bending(std::string_view name) { return find_name<FingerBending>(kBendingNames, name); }

HandPosture asl_handshape(AslHandshape shape) {
  const FingerFlexion* c = kCurled;
  const FingerSet middle = finger_bit(Finger::Middle);
  switch (shape) {
    case AslHandshape::A:
      return basic_handshape(BasicHandshape::Fist);
    case AslHandshape::B:
      return with(kThumbInPalm, kStraight, kStraight, kStraight, kStraight);
    case AslHandshape::C:
      return with(thumb(5, 45, 35, 10, 10), flex(35, 45, 20), flex(35, 45, 20), flex(35, 45, 20), flex(35, 45, 20));
    case AslHandshape::D: {
      // Index up; middle, ring and pinky round onto the opposed thumb tip (the "bowl" of the d).
      const FingerFlexion onto_thumb = flex(55, 60, 30);
      return with(thumb(20, 45, 55, 20, 15), kStraight, onto_thumb, onto_thumb, onto_thumb, {}, middle);
    }
    case AslHandshape::E: {
      // Fingertips curl down (large PIP, DIP near limit) to rest on the thumb tucked under them.
      const FingerFlexion curl = flex(60, 100, 75);
      return with(thumb(45, 15, 45, 40, 30), curl, curl, curl, curl);
    }
    case AslHandshape::F:
      return basic_handshape(BasicHandshape::Pinch12);
    case AslHandshape::G:
      // Index straight; thumb straight and roughly parallel to it (slight palmar abduction).
      return with(thumb(-10, 25, 5, 0, 0), kStraight, c[1], c[2], c[3]);
    case AslHandshape::I:
      return with(kThumbAcross, c[0], c[1], c[2], kStraight, spread(0, 0, 0, 10));
    case AslHandshape::K:
      // Index up; middle angled forward at the knuckle; thumb tip pressed between them on the
      // middle finger's proximal phalanx.
      return with(thumb(10, 45, 35, 10, 0), kStraight, flex(50, 0, 0), c[2], c[3], spread(8, 5, 0, 0), middle);
    case AslHandshape::L:
      return with(kThumbOut, kStraight, c[1], c[2], c[3]);
    case AslHandshape::M: {
      // Index, middle and ring folded over the thumb, whose tip pokes out between ring and pinky.
      const FingerFlexion over_thumb = flex(80, 85, 40);
      return with(thumb(50, 15, 45, 35, 15), over_thumb, over_thumb, over_thumb, c[3]);
    }
    case AslHandshape::N: {
      const FingerFlexion over_thumb = flex(80, 85, 40);
      return with(thumb(40, 15, 45, 35, 15), over_thumb, over_thumb, c[2], c[3]);
    }
    case AslHandshape::O: {
      // All fingers round onto the thumb tip: more PIP than the flat-O (pinchall) gives the round hole.
      return with(thumb(20, 45, 55, 20, 20), flex(45, 55, 30), flex(47, 55, 30), flex(50, 55, 30), flex(52, 55, 30),
                  spread(-3, 0, 3, 6), kAllFourFingers);
    }
    case AslHandshape::R: {
      HandPosture h = with(kThumbAcross, kStraight, kStraight, c[2], c[3], spread(0, -15, 0, 0));
      h.middle_crosses_index = true;
      return h;
    }
    case AslHandshape::S:
      return with(kThumbAcrossFist, c[0], c[1], c[2], c[3]);
    case AslHandshape::T:
      // Index hooked over the thumb, whose tip sits between index and middle.
      return with(thumb(25, 30, 35, 20, 5), flex(65, 85, 35), c[1], c[2], c[3]);
    case AslHandshape::U:
      return basic_handshape(BasicHandshape::Finger23);
    case AslHandshape::V:
      return basic_handshape(BasicHandshape::Finger23Spread);
    case AslHandshape::W:
      return with(thumb(45, 30, 55, 30, 25), kStraight, kStraight, kStraight, flex(75, 95, 50), spread(12, 0, 10, 0),
                  finger_bit(Finger::Pinky));
    case AslHandshape::X:
      return with(kThumbAcross, flex(20, 90, 60), c[1], c[2], c[3]);
    case AslHandshape::Y:
      return with(kThumbOut, c[0], c[1], c[2], kStraight, spread(0, 0, 0, 20));
    case AslHandshape::One:
      return basic_handshape(BasicHandshape::Finger2);
    case AslHandshape::Three:
      return with(kThumbOut, kStraight, kStraight, c[2], c[3], spread(12, 12, 0, 0));
    case AslHandshape::Four:
      return basic_handshape(BasicHandshape::Finger2345);
    case AslHandshape::Five:
      return make_handshape(BasicHandshape::Finger2345, ThumbModifier::Out);
    case AslHandshape::Six:
      // Thumb crosses the palm to the little finger: the largest opposition of the set.
      return with(thumb(40, 45, 60, 25, 15), kStraight, kStraight, kStraight, flex(50, 60, 30), spread(12, 0, 8, 0),
                  finger_bit(Finger::Pinky));
    case AslHandshape::Seven:
      return with(thumb(35, 45, 55, 20, 15), kStraight, kStraight, flex(50, 60, 30), kStraight, spread(12, 0, 0, 15),
                  finger_bit(Finger::Ring));
    case AslHandshape::Eight:
      return with(thumb(25, 45, 55, 20, 15), kStraight, flex(50, 55, 30), kStraight, kStraight, spread(12, 0, 0, 15),
                  middle);
  }
  return {};
}

std::string_view to_string(AslHandshape shape) { return kAslNames[static_cast<std::size_t>(shape)]; }
std::optional<AslHandshape> parse_asl_handshape(std::string_view name) {
  for (std::size_t k = 0; k < kAslHandshapeCount; ++k)
    if (name == kAslNames[k]) return static_cast<AslHandshape>(k);
  return std::nullopt;
}

}  // namespace gestura
