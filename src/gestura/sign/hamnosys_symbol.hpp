#pragma once
// The HamNoSys 4 symbol inventory: every symbol of the standard with its name (as used by the
// HamNoSys TeX package, the `names` fields of lexicons and SiGML element names), its Unicode
// private-use code point and the class of symbol it belongs to. The parser works on Symbol values,
// never on strings, so the three input forms (Unicode, name lists, SiGML) meet here.
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

namespace gestura::sign {

enum class Symbol : std::uint8_t {
  fist,
  flathand,
  finger2,
  finger23,
  finger23spread,
  finger2345,
  pinch12,
  pinchall,
  pinch12open,
  cee12,
  ceeall,
  ceeopen,
  thumboutmod,
  thumbacrossmod,
  thumbopenmod,
  fingerstraightmod,
  fingerbendmod,
  fingerhookmod,
  doublebent,
  doublehooked,
  extfingeru,
  extfingerur,
  extfingerr,
  extfingerdr,
  extfingerd,
  extfingerdl,
  extfingerl,
  extfingerul,
  extfingerol,
  extfingero,
  extfingeror,
  extfingeril,
  extfingeri,
  extfingerir,
  extfingerui,
  extfingerdi,
  extfingerdo,
  extfingeruo,
  palmu,
  palmur,
  palmr,
  palmdr,
  palmd,
  palmdl,
  palml,
  palmul,
  head,
  headtop,
  forehead,
  eyebrows,
  eyes,
  nose,
  nostrils,
  ear,
  earlobe,
  cheek,
  lips,
  tongue,
  teeth,
  chin,
  underchin,
  neck,
  shouldertop,
  shoulders,
  chest,
  stomach,
  belowstomach,
  neutralspace,
  upperarm,
  elbow,
  elbowinside,
  lowerarm,
  wristback,
  wristpulse,
  thumbball,
  palm,
  handback,
  thumbside,
  pinkyside,
  thumb,
  indexfinger,
  middlefinger,
  ringfinger,
  pinky,
  fingertip,
  fingernail,
  fingerpad,
  fingermidjoint,
  fingerbase,
  fingerside,
  lrbeside,
  lrat,
  coreftag,
  corefref,
  moveu,
  moveur,
  mover,
  movedr,
  moved,
  movedl,
  movel,
  moveul,
  moveol,
  moveo,
  moveor,
  moveil,
  movei,
  moveir,
  moveui,
  movedi,
  movedo,
  moveuo,
  circleo,
  circlei,
  circled,
  circleu,
  circlel,
  circler,
  circleul,
  circledr,
  circleur,
  circledl,
  circleol,
  circleir,
  circleor,
  circleil,
  circleui,
  circledo,
  circleuo,
  circledi,
  fingerplay,
  nodding,
  swinging,
  twisting,
  stircw,
  stirccw,
  replace,
  nomotion,
  clocku,
  clockul,
  clockl,
  clockdl,
  clockd,
  clockdr,
  clockr,
  clockur,
  clockfull,
  arcl,
  arcu,
  arcr,
  arcd,
  wavy,
  zigzag,
  ellipseh,
  ellipseur,
  ellipsev,
  ellipseul,
  increasing,
  decreasing,
  fast,
  slow,
  tense,
  rest,
  halt,
  close,
  touch,
  interlock,
  cross,
  armextended,
  behind,
  brushing,
  smallmod,
  largemod,
  repeatfromstart,
  repeatfromstartseveral,
  repeatcontinue,
  repeatcontinueseveral,
  repeatreverse,
  alternatingmotion,
  seqbegin,
  seqend,
  parbegin,
  parend,
  fusionbegin,
  fusionend,
  between,
  plus,
  symmpar,
  symmlr,
  nondominant,
  nonipsi,
  etc,
  orirelative,
  mime,
  version40,
  space,
  exclaim,
  comma,
  fullstop,
  query,
  altbegin,
  metaalt,
  altend,
  wristtopulse,
  wristtoback,
  wristtothumb,
  wristtopinky,
  movecross,
  moveX
};

// What role a symbol plays; parse errors name the class that was expected.
enum class SymbolClass : std::uint8_t {
  handshape,                  // basic forms: fist, flat hand, finger2 ... cee open
  thumb_modifier,             // thumb out / across / open
  finger_bending,             // bent at base, round, hooked, double bent, double hooked
  extended_finger_direction,  // where the extended fingers point
  palm_direction,             // where the palm faces
  finger,                     // thumb, index, middle, ring, pinky
  finger_part,                // tip, nail, pad, mid joint, base, side
  location_site,              // head, face, trunk, arm and hand sites
  location_side,              // beside / at the dominant side
  coreference,                // co-reference tag / reference to a tagged location
  straight_motion,            // 18 direction symbols (26 directions by combination)
  circular_motion,            // circles, by the axis they turn about
  circle_clock,               // where on the clock face a circle starts or ends
  arc,                        // bends a straight motion into an arc
  ellipse,                    // squashes a circle into an ellipse
  path_modifier,              // wavy / zigzag
  spiral_modifier,            // increasing / decreasing (spiral, growing or shrinking)
  size_modifier,              // small / large
  manner_modifier,            // fast, slow, tense, rest, halt
  contact,                    // close, touch, interlock, cross, arm extended, behind, brushing
  repetition,                 // from start, continued, reversed (once or several times)
  wrist_motion,               // nodding, swinging, twisting, stirring, wrist bending
  finger_play,                // wiggling fingers
  replacement,                // change of handshape / orientation / location
  other_motion,               // no motion, crossing motion, X-shaped motion
  structure,                  // sequence / parallel / fusion brackets, plus, between, alternatives
  two_handed,                 // symmetry operators, non-dominant, non-ipsilateral, alternating
  annotation,                 // etc, relative orientation, mime, version tag
  punctuation,                // space, comma, full stop, exclamation, question
};

struct SymbolInfo {
  Symbol symbol;
  std::string_view name;     // e.g. "hamflathand"
  char32_t codepoint;        // e.g. U+E001
  SymbolClass symbol_class;
};

// All symbols of the standard, in code point order of the HamNoSys 4 font table.
std::span<const SymbolInfo> symbol_table();

const SymbolInfo& symbol_info(Symbol symbol);
inline std::string_view symbol_name(Symbol s) { return symbol_info(s).name; }
inline SymbolClass symbol_class(Symbol s) { return symbol_info(s).symbol_class; }
std::string_view symbol_class_name(SymbolClass c);

// Accepts the standard names plus the aliases real SiGML files use (e.g. "hampinchopen").
std::optional<Symbol> symbol_from_name(std::string_view name);
std::optional<Symbol> symbol_from_codepoint(char32_t codepoint);

}  // namespace gestura::sign
