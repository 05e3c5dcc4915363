// Included by GLSL and by C++: the subset of syntax both languages share.
// C++ maps the GLSL vector types to glm; functions are declared with QL_FN so
// they are `inline` in C++ headers and plain in GLSL. Out-parameters use
// QL_INOUT(T) / QL_OUT(T) (a reference in C++).
#ifndef QLIGHT_SHARED_COMMON_H
#define QLIGHT_SHARED_COMMON_H

#ifdef __cplusplus
#include <cmath>
#include <cstdint>
#include <glm/glm.hpp>
namespace qlight::shared {
using namespace glm;
using uint = uint32_t;
}  // namespace qlight::shared
#define QL_FN inline
#define QL_INOUT(T) T&
#define QL_OUT(T) T&
#define QL_CONST constexpr
#define QL_BEGIN namespace qlight::shared {
#define QL_END }
// Pins a struct's layout so GLSL (scalar block layout) and C++ agree.
#define QL_CHECK_SIZE(T, bytes) static_assert(sizeof(T) == (bytes), #T " layout drifted")
#else
#define QL_FN
#define QL_INOUT(T) inout T
#define QL_OUT(T) out T
#define QL_CONST const
#define QL_BEGIN
#define QL_END
#define QL_CHECK_SIZE(T, bytes)
#endif

QL_BEGIN
QL_CONST float kPi = 3.14159265358979323846f;
QL_CONST float kInvPi = 0.31830988618379067154f;
QL_CONST float kTwoPi = 6.28318530717958647692f;
QL_END

#endif
