#pragma once
// Adding channel modifiers (noise, cycles, wave; anim/channel_modifier.h) from the curve
// editor, window-free: which channels an Add Modifier acts on, the defaults a new modifier
// gets, and the one undoable edit (Blender's Graph Editor > Channel > Add F-Curve Modifier).
#include <string>
#include <vector>

#include "anim/clip.h"
#include "editor/model/curve_editor.h"
#include "editor/model/document.h"

namespace kinema {

// The channels Add Modifier acts on: those holding a selected key of a shown curve, or,
// without selected keys, every channel the curve editor shows (the selected joints'), in
// clip order. Scalar channels are included; channels outside the clip are not.
std::vector<int> modifierTargetChannels(const Clip& clip, const JointSelection& selection,
                                        const CurveEditorState& state);

// A new modifier of `kind` for `channel`, with defaults sized to the channel's units:
// noise of 0.1 rad on rotations and Euler angles, 0.05 on translations, scales and scalars
// (0.5 s cells, 2 octaves, seed = the channel's joint so joints sway apart); cycles that
// repeat forever before and after; a wave of the same amplitude at 1 Hz with x the joint's
// rest position (model space) from `skeleton`.
ChannelModifier defaultChannelModifier(ChannelModifierKind kind, const Channel& channel, const Skeleton& skeleton);

// Appends a default modifier of `kind` to each of `channels` of clip `clipIndex` as one undo
// step labelled "Add Noise Modifier to 2 channels". Errors (nothing changed): no channels,
// a channel outside the clip, a Cycles modifier on a channel that has one already.
std::string addChannelModifierEdit(Document& doc, int clipIndex, const std::vector<int>& channels,
                                   ChannelModifierKind kind);

}  // namespace kinema
