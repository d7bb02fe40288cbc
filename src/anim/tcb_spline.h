#pragma once
#include "anim/clip.h"

namespace kinema {

// Incoming and outgoing tangents (value per second) of key k for Catmull-Rom and
// Kochanek-Bartels (TCB) segments.
//
// With chords a = f[k]-f[k-1] and b = f[k+1]-f[k], and T, C, B the key's tension,
// continuity and bias (all 0 for Catmull-Rom):
//   out = [(1-T)(1+C)(1+B) a + (1-T)(1-C)(1-B) b] / (t[k+1]-t[k-1])
//   in  = [(1-T)(1-C)(1+B) a + (1-T)(1+C)(1-B) b] / (t[k+1]-t[k-1])
// Dividing by the whole span is Kochanek and Bartels' correction for uneven key spacing
// written per second, so in == out (C1) whenever C == 0, and T=C=B=0 gives Catmull-Rom
// (f[k+1]-f[k-1]) / (t[k+1]-t[k-1]). B > 0 weights the chord from the left neighbour, so
// the curve keeps going that way past the key (overshoot); B < 0 weights the right chord
// (anticipation before the key). (Seed 003 prints the two chords swapped against its text;
// this follows the text and Kochanek-Bartels' paper.)
// End keys use the natural end condition: the tangent for which the end segment has no
// curvature at the end key, (3 chord/dt - neighbour tangent) / 2; a two-key channel is a line.
void tcbTangents(const Channel& channel, int key, bool useKeyTcb, glm::vec4& in, glm::vec4& out);

}  // namespace kinema
