#pragma once
// Names of the face's scalar channels in a Clip. The viseme and expression names are the avatar's
// morph target names, so a renderer maps a channel to a morph target by name; the last group are
// channels no morph target has, which the lead drives joints from. A rename is an edit here only.
#include <array>
#include <string_view>

namespace gestura::face {

// The 15 visemes (MPEG-4 / Oculus set).
inline constexpr std::string_view kSil = "sil", kPP = "PP", kFF = "FF", kTH = "TH", kDD = "DD",
                                  kKK = "kk", kCH = "CH", kSS = "SS", kNN = "nn", kRR = "RR",
                                  kAA = "aa", kE = "E", kIH = "ih", kOH = "oh", kOU = "ou";
inline constexpr std::array<std::string_view, 15> kVisemes{kSil, kPP, kFF, kTH, kDD, kKK, kCH, kSS,
                                                           kNN, kRR, kAA, kE,  kIH, kOH, kOU};

// Expression morph targets.
inline constexpr std::string_view kBrowInnerUpL = "browInnerUp_L", kBrowInnerUpR = "browInnerUp_R",
                                  kBrowOuterUpL = "browOuterUp_L", kBrowOuterUpR = "browOuterUp_R",
                                  kBrowDownL = "browDown_L", kBrowDownR = "browDown_R",
                                  kEyeBlinkL = "eyeBlink_L", kEyeBlinkR = "eyeBlink_R",
                                  kEyeWideL = "eyeWide_L", kEyeWideR = "eyeWide_R",
                                  kEyeSquintL = "eyeSquint_L", kEyeSquintR = "eyeSquint_R",
                                  kCheekPuff = "cheekPuff", kMouthSmileL = "mouthSmile_L",
                                  kMouthSmileR = "mouthSmile_R", kMouthFrownL = "mouthFrown_L",
                                  kMouthFrownR = "mouthFrown_R", kMouthPucker = "mouthPucker",
                                  kMouthPress = "mouthPress", kMouthOpen = "mouthOpen",
                                  kTongueOut = "tongueOut";

// Channels without a morph target:
//  jaw_open   0..1, opening of the jaw; drive temporomandibular x = jaw_open * kJawOpenMaxDegrees.
//             Visemes shape the lips only, so mouthing and an expression never fight over the jaw.
//  gaze_hands 0..1, how much the eyes look at the dominant hand (fingerspelling); write_eye_gaze
//             (eye_gaze.hpp) turns the eyeball joints from straight ahead (0) to the hand (1).
inline constexpr std::string_view kJawOpen = "jaw_open";
inline constexpr std::string_view kGazeHands = "gaze_hands";
inline constexpr float kJawOpenMaxDegrees = 20.0f;  // well inside the joint's −2..28° limit

}  // namespace gestura::face
