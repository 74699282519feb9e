#pragma once
// Facial morph targets of the default avatar, made by region-based free-form deformation
// (realtime-virtual-humans.txt §5.1): each morph is a sum of displacement fields, each confined to
// a region of the face with a smooth (1 − r²)² falloff — lift a brow, pull the lips towards the
// mouth centre — plus two rotations: the lower face, lower teeth and tongue turn about the jaw
// joint by their jaw skin weight (so a morph opens the mouth exactly as the jaw bone does), and a
// lid turns about its eye's centre, sliding over the eyeball.
//
// Naming (camelCase with _L / _R for the avatar's left / right, as in ARKit blend shapes):
//   visemes (Oculus/MPEG-4-style set): sil PP FF TH DD kk CH SS nn RR aa E ih oh ou
//   browInnerUp_L/R browOuterUp_L/R browDown_L/R eyeBlink_L/R eyeWide_L/R eyeSquint_L/R cheekPuff
//   mouthSmile_L/R (lip corner up) mouthFrown_L/R mouthPucker mouthPress mouthOpen tongueOut
// The rigid face parts (face_parts.hpp) only ever move rigidly: eyeballs not at all (gaze is the eye
// joints'), teeth with the jaw, the tongue with the jaw and by its own forward/up shift.
#include <array>
#include <string_view>
#include <utility>
#include <vector>

#include "gestura/body/head_sculpt.hpp"
#include "gestura/body/mesh.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura {

inline constexpr std::array<std::string_view, 15> kVisemeNames{"sil", "PP", "FF", "TH", "DD", "kk", "CH", "SS",
                                                               "nn",  "RR", "aa", "E",  "ih", "oh", "ou"};
inline constexpr std::array<std::string_view, 21> kExpressionMorphNames{
    "browInnerUp_L", "browInnerUp_R", "browOuterUp_L", "browOuterUp_R", "browDown_L",   "browDown_R",
    "eyeBlink_L",    "eyeBlink_R",    "eyeWide_L",     "eyeWide_R",     "eyeSquint_L",  "eyeSquint_R",
    "cheekPuff",     "mouthSmile_L",  "mouthSmile_R",  "mouthFrown_L",  "mouthFrown_R", "mouthPucker",
    "mouthPress",    "mouthOpen",     "tongueOut"};

// All morphs above, visemes first, placed by the head's landmarks (head_sculpt.hpp). Only vertices
// of the head move. `mesh` needs its materials (they tell the rigid parts apart) and skin weights
// (the jaw's).
std::vector<MorphTarget> build_face_morphs(const Skeleton& skeleton, const Mesh& mesh, const FaceLandmarks& marks);

// Fills every morph's normal_deltas: the change of the area-weighted vertex normal when the morph
// is applied at full weight (computed on the tessellation, so rest and morphed normals compare).
void compute_morph_normal_deltas(Mesh& mesh);

// The six universal expressions of MPEG-4 facial animation plus neutral.
enum class Expression { Neutral, Joy, Sadness, Anger, Fear, Disgust, Surprise };
inline constexpr std::array<std::string_view, 7> kExpressionNames{"neutral", "joy",     "sadness", "anger",
                                                                  "fear",    "disgust", "surprise"};
// Throws gestura::Error for an unknown name.
Expression parse_expression(std::string_view name);

// The expression as weights over the named morphs (the table in face_morphs.cpp).
std::vector<std::pair<std::string_view, float>> expression_weights(Expression expression);

// Weights for every morph of `mesh` (0 for morphs the expression does not use), times intensity.
std::vector<float> expression_morph_weights(const Mesh& mesh, Expression expression, float intensity = 1.0f);

// V' = V + Σ w·ΔV. weights.size() must equal mesh.morphs.size().
std::vector<vec3> apply_morphs(const Mesh& mesh, const std::vector<float>& weights);

}  // namespace gestura
