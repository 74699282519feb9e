#include "gestura/sign/hamnosys_symbol.hpp"

#include <unordered_map>
#include <utility>

namespace gestura::sign {
namespace {

// Names and code points are those of the HamNoSys 4 standard (the HamNoSysUnicode font);
// tests/sign/hamnosys_symbol_test.cpp cross-checks this table against the published list.
constexpr SymbolInfo kSymbols[] = {
    {Symbol::fist, "hamfist", 0xE000, SymbolClass::handshape},
    {Symbol::flathand, "hamflathand", 0xE001, SymbolClass::handshape},
    {Symbol::finger2, "hamfinger2", 0xE002, SymbolClass::handshape},
    {Symbol::finger23, "hamfinger23", 0xE003, SymbolClass::handshape},
    {Symbol::finger23spread, "hamfinger23spread", 0xE004, SymbolClass::handshape},
    {Symbol::finger2345, "hamfinger2345", 0xE005, SymbolClass::handshape},
    {Symbol::pinch12, "hampinch12", 0xE006, SymbolClass::handshape},
    {Symbol::pinchall, "hampinchall", 0xE007, SymbolClass::handshape},
    {Symbol::pinch12open, "hampinch12open", 0xE008, SymbolClass::handshape},
    {Symbol::cee12, "hamcee12", 0xE009, SymbolClass::handshape},
    {Symbol::ceeall, "hamceeall", 0xE00A, SymbolClass::handshape},
    {Symbol::ceeopen, "hamceeopen", 0xE00B, SymbolClass::handshape},
    {Symbol::thumboutmod, "hamthumboutmod", 0xE00C, SymbolClass::thumb_modifier},
    {Symbol::thumbacrossmod, "hamthumbacrossmod", 0xE00D, SymbolClass::thumb_modifier},
    {Symbol::thumbopenmod, "hamthumbopenmod", 0xE00E, SymbolClass::thumb_modifier},
    {Symbol::fingerstraightmod, "hamfingerstraightmod", 0xE010, SymbolClass::finger_bending},
    {Symbol::fingerbendmod, "hamfingerbendmod", 0xE011, SymbolClass::finger_bending},
    {Symbol::fingerhookmod, "hamfingerhookmod", 0xE012, SymbolClass::finger_bending},
    {Symbol::doublebent, "hamdoublebent", 0xE013, SymbolClass::finger_bending},
    {Symbol::doublehooked, "hamdoublehooked", 0xE014, SymbolClass::finger_bending},
    {Symbol::extfingeru, "hamextfingeru", 0xE020, SymbolClass::extended_finger_direction},
    {Symbol::extfingerur, "hamextfingerur", 0xE021, SymbolClass::extended_finger_direction},
    {Symbol::extfingerr, "hamextfingerr", 0xE022, SymbolClass::extended_finger_direction},
    {Symbol::extfingerdr, "hamextfingerdr", 0xE023, SymbolClass::extended_finger_direction},
    {Symbol::extfingerd, "hamextfingerd", 0xE024, SymbolClass::extended_finger_direction},
    {Symbol::extfingerdl, "hamextfingerdl", 0xE025, SymbolClass::extended_finger_direction},
    {Symbol::extfingerl, "hamextfingerl", 0xE026, SymbolClass::extended_finger_direction},
    {Symbol::extfingerul, "hamextfingerul", 0xE027, SymbolClass::extended_finger_direction},
    {Symbol::extfingerol, "hamextfingerol", 0xE028, SymbolClass::extended_finger_direction},
    {Symbol::extfingero, "hamextfingero", 0xE029, SymbolClass::extended_finger_direction},
    {Symbol::extfingeror, "hamextfingeror", 0xE02A, SymbolClass::extended_finger_direction},
    {Symbol::extfingeril, "hamextfingeril", 0xE02B, SymbolClass::extended_finger_direction},
    {Symbol::extfingeri, "hamextfingeri", 0xE02C, SymbolClass::extended_finger_direction},
    {Symbol::extfingerir, "hamextfingerir", 0xE02D, SymbolClass::extended_finger_direction},
    {Symbol::extfingerui, "hamextfingerui", 0xE02E, SymbolClass::extended_finger_direction},
    {Symbol::extfingerdi, "hamextfingerdi", 0xE02F, SymbolClass::extended_finger_direction},
    {Symbol::extfingerdo, "hamextfingerdo", 0xE030, SymbolClass::extended_finger_direction},
    {Symbol::extfingeruo, "hamextfingeruo", 0xE031, SymbolClass::extended_finger_direction},
    {Symbol::palmu, "hampalmu", 0xE038, SymbolClass::palm_direction},
    {Symbol::palmur, "hampalmur", 0xE039, SymbolClass::palm_direction},
    {Symbol::palmr, "hampalmr", 0xE03A, SymbolClass::palm_direction},
    {Symbol::palmdr, "hampalmdr", 0xE03B, SymbolClass::palm_direction},
    {Symbol::palmd, "hampalmd", 0xE03C, SymbolClass::palm_direction},
    {Symbol::palmdl, "hampalmdl", 0xE03D, SymbolClass::palm_direction},
    {Symbol::palml, "hampalml", 0xE03E, SymbolClass::palm_direction},
    {Symbol::palmul, "hampalmul", 0xE03F, SymbolClass::palm_direction},
    {Symbol::head, "hamhead", 0xE040, SymbolClass::location_site},
    {Symbol::headtop, "hamheadtop", 0xE041, SymbolClass::location_site},
    {Symbol::forehead, "hamforehead", 0xE042, SymbolClass::location_site},
    {Symbol::eyebrows, "hameyebrows", 0xE043, SymbolClass::location_site},
    {Symbol::eyes, "hameyes", 0xE044, SymbolClass::location_site},
    {Symbol::nose, "hamnose", 0xE045, SymbolClass::location_site},
    {Symbol::nostrils, "hamnostrils", 0xE046, SymbolClass::location_site},
    {Symbol::ear, "hamear", 0xE047, SymbolClass::location_site},
    {Symbol::earlobe, "hamearlobe", 0xE048, SymbolClass::location_site},
    {Symbol::cheek, "hamcheek", 0xE049, SymbolClass::location_site},
    {Symbol::lips, "hamlips", 0xE04A, SymbolClass::location_site},
    {Symbol::tongue, "hamtongue", 0xE04B, SymbolClass::location_site},
    {Symbol::teeth, "hamteeth", 0xE04C, SymbolClass::location_site},
    {Symbol::chin, "hamchin", 0xE04D, SymbolClass::location_site},
    {Symbol::underchin, "hamunderchin", 0xE04E, SymbolClass::location_site},
    {Symbol::neck, "hamneck", 0xE04F, SymbolClass::location_site},
    {Symbol::shouldertop, "hamshouldertop", 0xE050, SymbolClass::location_site},
    {Symbol::shoulders, "hamshoulders", 0xE051, SymbolClass::location_site},
    {Symbol::chest, "hamchest", 0xE052, SymbolClass::location_site},
    {Symbol::stomach, "hamstomach", 0xE053, SymbolClass::location_site},
    {Symbol::belowstomach, "hambelowstomach", 0xE054, SymbolClass::location_site},
    {Symbol::neutralspace, "hamneutralspace", 0xE05F, SymbolClass::location_site},
    {Symbol::upperarm, "hamupperarm", 0xE060, SymbolClass::location_site},
    {Symbol::elbow, "hamelbow", 0xE061, SymbolClass::location_site},
    {Symbol::elbowinside, "hamelbowinside", 0xE062, SymbolClass::location_site},
    {Symbol::lowerarm, "hamlowerarm", 0xE063, SymbolClass::location_site},
    {Symbol::wristback, "hamwristback", 0xE064, SymbolClass::location_site},
    {Symbol::wristpulse, "hamwristpulse", 0xE065, SymbolClass::location_site},
    {Symbol::thumbball, "hamthumbball", 0xE066, SymbolClass::location_site},
    {Symbol::palm, "hampalm", 0xE067, SymbolClass::location_site},
    {Symbol::handback, "hamhandback", 0xE068, SymbolClass::location_site},
    {Symbol::thumbside, "hamthumbside", 0xE069, SymbolClass::location_site},
    {Symbol::pinkyside, "hampinkyside", 0xE06A, SymbolClass::location_site},
    {Symbol::thumb, "hamthumb", 0xE070, SymbolClass::finger},
    {Symbol::indexfinger, "hamindexfinger", 0xE071, SymbolClass::finger},
    {Symbol::middlefinger, "hammiddlefinger", 0xE072, SymbolClass::finger},
    {Symbol::ringfinger, "hamringfinger", 0xE073, SymbolClass::finger},
    {Symbol::pinky, "hampinky", 0xE074, SymbolClass::finger},
    {Symbol::fingertip, "hamfingertip", 0xE075, SymbolClass::finger_part},
    {Symbol::fingernail, "hamfingernail", 0xE076, SymbolClass::finger_part},
    {Symbol::fingerpad, "hamfingerpad", 0xE077, SymbolClass::finger_part},
    {Symbol::fingermidjoint, "hamfingermidjoint", 0xE078, SymbolClass::finger_part},
    {Symbol::fingerbase, "hamfingerbase", 0xE079, SymbolClass::finger_part},
    {Symbol::fingerside, "hamfingerside", 0xE07A, SymbolClass::finger_part},
    {Symbol::lrbeside, "hamlrbeside", 0xE058, SymbolClass::location_side},
    {Symbol::lrat, "hamlrat", 0xE059, SymbolClass::location_side},
    {Symbol::coreftag, "hamcoreftag", 0xE05A, SymbolClass::coreference},
    {Symbol::corefref, "hamcorefref", 0xE05B, SymbolClass::coreference},
    {Symbol::moveu, "hammoveu", 0xE080, SymbolClass::straight_motion},
    {Symbol::moveur, "hammoveur", 0xE081, SymbolClass::straight_motion},
    {Symbol::mover, "hammover", 0xE082, SymbolClass::straight_motion},
    {Symbol::movedr, "hammovedr", 0xE083, SymbolClass::straight_motion},
    {Symbol::moved, "hammoved", 0xE084, SymbolClass::straight_motion},
    {Symbol::movedl, "hammovedl", 0xE085, SymbolClass::straight_motion},
    {Symbol::movel, "hammovel", 0xE086, SymbolClass::straight_motion},
    {Symbol::moveul, "hammoveul", 0xE087, SymbolClass::straight_motion},
    {Symbol::moveol, "hammoveol", 0xE088, SymbolClass::straight_motion},
    {Symbol::moveo, "hammoveo", 0xE089, SymbolClass::straight_motion},
    {Symbol::moveor, "hammoveor", 0xE08A, SymbolClass::straight_motion},
    {Symbol::moveil, "hammoveil", 0xE08B, SymbolClass::straight_motion},
    {Symbol::movei, "hammovei", 0xE08C, SymbolClass::straight_motion},
    {Symbol::moveir, "hammoveir", 0xE08D, SymbolClass::straight_motion},
    {Symbol::moveui, "hammoveui", 0xE08E, SymbolClass::straight_motion},
    {Symbol::movedi, "hammovedi", 0xE08F, SymbolClass::straight_motion},
    {Symbol::movedo, "hammovedo", 0xE090, SymbolClass::straight_motion},
    {Symbol::moveuo, "hammoveuo", 0xE091, SymbolClass::straight_motion},
    {Symbol::circleo, "hamcircleo", 0xE092, SymbolClass::circular_motion},
    {Symbol::circlei, "hamcirclei", 0xE093, SymbolClass::circular_motion},
    {Symbol::circled, "hamcircled", 0xE094, SymbolClass::circular_motion},
    {Symbol::circleu, "hamcircleu", 0xE095, SymbolClass::circular_motion},
    {Symbol::circlel, "hamcirclel", 0xE096, SymbolClass::circular_motion},
    {Symbol::circler, "hamcircler", 0xE097, SymbolClass::circular_motion},
    {Symbol::circleul, "hamcircleul", 0xE098, SymbolClass::circular_motion},
    {Symbol::circledr, "hamcircledr", 0xE099, SymbolClass::circular_motion},
    {Symbol::circleur, "hamcircleur", 0xE09A, SymbolClass::circular_motion},
    {Symbol::circledl, "hamcircledl", 0xE09B, SymbolClass::circular_motion},
    {Symbol::circleol, "hamcircleol", 0xE09C, SymbolClass::circular_motion},
    {Symbol::circleir, "hamcircleir", 0xE09D, SymbolClass::circular_motion},
    {Symbol::circleor, "hamcircleor", 0xE09E, SymbolClass::circular_motion},
    {Symbol::circleil, "hamcircleil", 0xE09F, SymbolClass::circular_motion},
    {Symbol::circleui, "hamcircleui", 0xE0A0, SymbolClass::circular_motion},
    {Symbol::circledo, "hamcircledo", 0xE0A1, SymbolClass::circular_motion},
    {Symbol::circleuo, "hamcircleuo", 0xE0A2, SymbolClass::circular_motion},
    {Symbol::circledi, "hamcircledi", 0xE0A3, SymbolClass::circular_motion},
    {Symbol::fingerplay, "hamfingerplay", 0xE0A4, SymbolClass::finger_play},
    {Symbol::nodding, "hamnodding", 0xE0A5, SymbolClass::wrist_motion},
    {Symbol::swinging, "hamswinging", 0xE0A6, SymbolClass::wrist_motion},
    {Symbol::twisting, "hamtwisting", 0xE0A7, SymbolClass::wrist_motion},
    {Symbol::stircw, "hamstircw", 0xE0A8, SymbolClass::wrist_motion},
    {Symbol::stirccw, "hamstirccw", 0xE0A9, SymbolClass::wrist_motion},
    {Symbol::replace, "hamreplace", 0xE0AA, SymbolClass::replacement},
    {Symbol::nomotion, "hamnomotion", 0xE0AF, SymbolClass::other_motion},
    {Symbol::clocku, "hamclocku", 0xE0B0, SymbolClass::circle_clock},
    {Symbol::clockul, "hamclockul", 0xE0B1, SymbolClass::circle_clock},
    {Symbol::clockl, "hamclockl", 0xE0B2, SymbolClass::circle_clock},
    {Symbol::clockdl, "hamclockdl", 0xE0B3, SymbolClass::circle_clock},
    {Symbol::clockd, "hamclockd", 0xE0B4, SymbolClass::circle_clock},
    {Symbol::clockdr, "hamclockdr", 0xE0B5, SymbolClass::circle_clock},
    {Symbol::clockr, "hamclockr", 0xE0B6, SymbolClass::circle_clock},
    {Symbol::clockur, "hamclockur", 0xE0B7, SymbolClass::circle_clock},
    {Symbol::clockfull, "hamclockfull", 0xE0B8, SymbolClass::circle_clock},
    {Symbol::arcl, "hamarcl", 0xE0B9, SymbolClass::arc},
    {Symbol::arcu, "hamarcu", 0xE0BA, SymbolClass::arc},
    {Symbol::arcr, "hamarcr", 0xE0BB, SymbolClass::arc},
    {Symbol::arcd, "hamarcd", 0xE0BC, SymbolClass::arc},
    {Symbol::wavy, "hamwavy", 0xE0BD, SymbolClass::path_modifier},
    {Symbol::zigzag, "hamzigzag", 0xE0BE, SymbolClass::path_modifier},
    {Symbol::ellipseh, "hamellipseh", 0xE0C0, SymbolClass::ellipse},
    {Symbol::ellipseur, "hamellipseur", 0xE0C1, SymbolClass::ellipse},
    {Symbol::ellipsev, "hamellipsev", 0xE0C2, SymbolClass::ellipse},
    {Symbol::ellipseul, "hamellipseul", 0xE0C3, SymbolClass::ellipse},
    {Symbol::increasing, "hamincreasing", 0xE0C4, SymbolClass::spiral_modifier},
    {Symbol::decreasing, "hamdecreasing", 0xE0C5, SymbolClass::spiral_modifier},
    {Symbol::fast, "hamfast", 0xE0C8, SymbolClass::manner_modifier},
    {Symbol::slow, "hamslow", 0xE0C9, SymbolClass::manner_modifier},
    {Symbol::tense, "hamtense", 0xE0CA, SymbolClass::manner_modifier},
    {Symbol::rest, "hamrest", 0xE0CB, SymbolClass::manner_modifier},
    {Symbol::halt, "hamhalt", 0xE0CC, SymbolClass::manner_modifier},
    {Symbol::close, "hamclose", 0xE0D0, SymbolClass::contact},
    {Symbol::touch, "hamtouch", 0xE0D1, SymbolClass::contact},
    {Symbol::interlock, "haminterlock", 0xE0D2, SymbolClass::contact},
    {Symbol::cross, "hamcross", 0xE0D3, SymbolClass::contact},
    {Symbol::armextended, "hamarmextended", 0xE0D4, SymbolClass::contact},
    {Symbol::behind, "hambehind", 0xE0D5, SymbolClass::contact},
    {Symbol::brushing, "hambrushing", 0xE0D6, SymbolClass::contact},
    {Symbol::smallmod, "hamsmallmod", 0xE0C6, SymbolClass::size_modifier},
    {Symbol::largemod, "hamlargemod", 0xE0C7, SymbolClass::size_modifier},
    {Symbol::repeatfromstart, "hamrepeatfromstart", 0xE0D8, SymbolClass::repetition},
    {Symbol::repeatfromstartseveral, "hamrepeatfromstartseveral", 0xE0D9, SymbolClass::repetition},
    {Symbol::repeatcontinue, "hamrepeatcontinue", 0xE0DA, SymbolClass::repetition},
    {Symbol::repeatcontinueseveral, "hamrepeatcontinueseveral", 0xE0DB, SymbolClass::repetition},
    {Symbol::repeatreverse, "hamrepeatreverse", 0xE0DC, SymbolClass::repetition},
    {Symbol::alternatingmotion, "hamalternatingmotion", 0xE0DD, SymbolClass::two_handed},
    {Symbol::seqbegin, "hamseqbegin", 0xE0E0, SymbolClass::structure},
    {Symbol::seqend, "hamseqend", 0xE0E1, SymbolClass::structure},
    {Symbol::parbegin, "hamparbegin", 0xE0E2, SymbolClass::structure},
    {Symbol::parend, "hamparend", 0xE0E3, SymbolClass::structure},
    {Symbol::fusionbegin, "hamfusionbegin", 0xE0E4, SymbolClass::structure},
    {Symbol::fusionend, "hamfusionend", 0xE0E5, SymbolClass::structure},
    {Symbol::between, "hambetween", 0xE0E6, SymbolClass::structure},
    {Symbol::plus, "hamplus", 0xE0E7, SymbolClass::structure},
    {Symbol::symmpar, "hamsymmpar", 0xE0E8, SymbolClass::two_handed},
    {Symbol::symmlr, "hamsymmlr", 0xE0E9, SymbolClass::two_handed},
    {Symbol::nondominant, "hamnondominant", 0xE0EA, SymbolClass::two_handed},
    {Symbol::nonipsi, "hamnonipsi", 0xE0EB, SymbolClass::two_handed},
    {Symbol::etc, "hametc", 0xE0EC, SymbolClass::annotation},
    {Symbol::orirelative, "hamorirelative", 0xE0ED, SymbolClass::annotation},
    {Symbol::mime, "hammime", 0xE0F0, SymbolClass::annotation},
    {Symbol::version40, "hamversion40", 0xE0F1, SymbolClass::annotation},
    {Symbol::space, "hamspace", 0x0020, SymbolClass::punctuation},
    {Symbol::exclaim, "hamexclaim", 0x0021, SymbolClass::punctuation},
    {Symbol::comma, "hamcomma", 0x002C, SymbolClass::punctuation},
    {Symbol::fullstop, "hamfullstop", 0x002E, SymbolClass::punctuation},
    {Symbol::query, "hamquery", 0x003F, SymbolClass::punctuation},
    {Symbol::altbegin, "hamaltbegin", 0x007B, SymbolClass::structure},
    {Symbol::metaalt, "hammetaalt", 0x007C, SymbolClass::structure},
    {Symbol::altend, "hamaltend", 0x007D, SymbolClass::structure},
    {Symbol::wristtopulse, "hamwristtopulse", 0xE07C, SymbolClass::wrist_motion},
    {Symbol::wristtoback, "hamwristtoback", 0xE07D, SymbolClass::wrist_motion},
    {Symbol::wristtothumb, "hamwristtothumb", 0xE07E, SymbolClass::wrist_motion},
    {Symbol::wristtopinky, "hamwristtopinky", 0xE07F, SymbolClass::wrist_motion},
    {Symbol::movecross, "hammovecross", 0xE0AD, SymbolClass::other_motion},
    {Symbol::moveX, "hammoveX", 0xE0AE, SymbolClass::other_motion},
};

constexpr std::size_t kSymbolCount = sizeof(kSymbols) / sizeof(kSymbols[0]);

// The table is indexed by the enum value, so a lookup is one array access.
constexpr bool table_in_enum_order() {
  for (std::size_t i = 0; i < kSymbolCount; ++i)
    if (static_cast<std::size_t>(kSymbols[i].symbol) != i) return false;
  return true;
}
static_assert(table_in_enum_order(), "kSymbols must list the symbols in enum order");

// Spellings found in real SiGML files that differ from the standard names.
constexpr std::pair<std::string_view, Symbol> kAliases[] = {
    {"hampinchopen", Symbol::pinch12open},
    {"hamcee12open", Symbol::ceeopen},
};

}  // namespace

std::span<const SymbolInfo> symbol_table() { return kSymbols; }

const SymbolInfo& symbol_info(Symbol symbol) { return kSymbols[static_cast<std::size_t>(symbol)]; }

std::string_view symbol_class_name(SymbolClass c) {
  switch (c) {
    case SymbolClass::handshape: return "handshape";
    case SymbolClass::thumb_modifier: return "thumb modifier";
    case SymbolClass::finger_bending: return "finger bending";
    case SymbolClass::extended_finger_direction: return "extended finger direction";
    case SymbolClass::palm_direction: return "palm orientation";
    case SymbolClass::finger: return "finger";
    case SymbolClass::finger_part: return "finger part";
    case SymbolClass::location_site: return "location";
    case SymbolClass::location_side: return "location side";
    case SymbolClass::coreference: return "co-reference";
    case SymbolClass::straight_motion: return "straight motion";
    case SymbolClass::circular_motion: return "circular motion";
    case SymbolClass::circle_clock: return "circle clock position";
    case SymbolClass::arc: return "arc";
    case SymbolClass::ellipse: return "ellipse";
    case SymbolClass::path_modifier: return "path modifier";
    case SymbolClass::spiral_modifier: return "spiral modifier";
    case SymbolClass::size_modifier: return "size modifier";
    case SymbolClass::manner_modifier: return "manner modifier";
    case SymbolClass::contact: return "contact";
    case SymbolClass::repetition: return "repetition";
    case SymbolClass::wrist_motion: return "wrist motion";
    case SymbolClass::finger_play: return "finger play";
    case SymbolClass::replacement: return "replacement";
    case SymbolClass::other_motion: return "motion";
    case SymbolClass::structure: return "structure";
    case SymbolClass::two_handed: return "two-handed operator";
    case SymbolClass::annotation: return "annotation";
    case SymbolClass::punctuation: return "punctuation";
  }
  return "symbol";
}

std::optional<Symbol> symbol_from_name(std::string_view name) {
  static const std::unordered_map<std::string_view, Symbol> by_name = [] {
    std::unordered_map<std::string_view, Symbol> map;
    for (const SymbolInfo& s : kSymbols) map.emplace(s.name, s.symbol);
    for (const auto& [alias, symbol] : kAliases) map.emplace(alias, symbol);
    return map;
  }();
  const auto it = by_name.find(name);
  if (it == by_name.end()) return std::nullopt;
  return it->second;
}

std::optional<Symbol> symbol_from_codepoint(char32_t codepoint) {
  static const std::unordered_map<char32_t, Symbol> by_codepoint = [] {
    std::unordered_map<char32_t, Symbol> map;
    for (const SymbolInfo& s : kSymbols) map.emplace(s.codepoint, s.symbol);
    return map;
  }();
  const auto it = by_codepoint.find(codepoint);
  if (it == by_codepoint.end()) return std::nullopt;
  return it->second;
}

}  // namespace gestura::sign
