// glTF animations → Clips (see gltf_import_parts.h). STEP, LINEAR and CUBICSPLINE map onto
// the keyframe engine's Step, Linear (rotations: shortest-arc slerp) and Hermite, whose
// segment formula is glTF's: tangents in value per second scaled by the key interval,
// rotations interpolated component-wise and then normalised.
#include <tiny_gltf.h>

#include <cmath>

#include "core/rotation.h"
#include "io/gltf_import_parts.h"

namespace kinema {

namespace {

// The number of morph targets node `node` shows (0 without a mesh).
size_t morphTargetsOf(const GltfContext& ctx, const Scene& scene, int node) {
  const int mesh = ctx.model.nodes[node].mesh;
  if (mesh < 0 || static_cast<size_t>(mesh) >= scene.meshes.size()) return 0;
  return scene.meshes[mesh].morphWeights.size();
}

}  // namespace

std::string importAnimations(GltfContext& ctx, const std::vector<int>& jointOfNode, Scene& scene,
                             bool writtenByKinema) {
  const tinygltf::Model& m = ctx.model;
  const int nodes = static_cast<int>(jointOfNode.size());
  for (size_t a = 0; a < m.animations.size(); ++a) {
    const tinygltf::Animation& anim = m.animations[a];
    Clip clip;
    clip.name = anim.name.empty() ? "animation_" + std::to_string(a) : anim.name;
    for (size_t c = 0; c < anim.channels.size(); ++c) {
      const tinygltf::AnimationChannel& ch = anim.channels[c];
      const std::string where = "animation " + std::to_string(a) + " channel " + std::to_string(c);
      if (ch.sampler < 0 || static_cast<size_t>(ch.sampler) >= anim.samplers.size())
        return ctx.error(where + ": sampler " + std::to_string(ch.sampler) + " does not exist");
      if (ch.target_node < 0) {
        ctx.warn(where + ": has no target node (an extension's target), not kept");
        continue;
      }
      if (ch.target_node >= nodes)
        return ctx.error(where + ": target node " + std::to_string(ch.target_node) + " does not exist");
      const std::string& path = ch.target_path;
      int components = 0;
      ChannelTarget target = ChannelTarget::Translation;
      if (path == "translation") components = 3, target = ChannelTarget::Translation;
      else if (path == "rotation") components = 4, target = ChannelTarget::Rotation;
      else if (path == "scale") components = 3, target = ChannelTarget::Scale;
      else if (path == "weights") components = 1, target = ChannelTarget::Scalar;
      else {
        ctx.warn(where + ": target path '" + path + "' is not kept");
        continue;
      }
      const size_t perKey = target == ChannelTarget::Scalar ? morphTargetsOf(ctx, scene, ch.target_node) : 1;
      if (perKey == 0) return ctx.error(where + ": animates the weights of node " + std::to_string(ch.target_node) +
                                        ", which shows no morph targets");

      const tinygltf::AnimationSampler& s = anim.samplers[ch.sampler];
      const std::string sw = "animation " + std::to_string(a) + " sampler " + std::to_string(ch.sampler);
      Interpolation interpolation;
      if (s.interpolation == "LINEAR" || s.interpolation.empty()) interpolation = Interpolation::Linear;
      else if (s.interpolation == "STEP") interpolation = Interpolation::Step;
      else if (s.interpolation == "CUBICSPLINE") interpolation = Interpolation::Hermite;
      else return ctx.error(sw + ": interpolation '" + s.interpolation + "' is not LINEAR, STEP or CUBICSPLINE");
      const bool cubic = interpolation == Interpolation::Hermite;

      std::vector<float> times, out;
      if (std::string e = readFloatAccessor(ctx, s.input, 1, kCompFloat, sw + " input", times); !e.empty()) return e;
      for (size_t k = 1; k < times.size(); ++k)
        if (!(times[k] > times[k - 1]))
          return ctx.error(sw + " input accessor " + std::to_string(s.input) + ": key times are not increasing at key " +
                           std::to_string(k) + " (" + std::to_string(times[k - 1]) + " then " +
                           std::to_string(times[k]) + ")");
      const size_t keys = times.size();
      const size_t expected = keys * perKey * (cubic ? 3 : 1);
      if (accessorCount(ctx, s.output) != expected && accessorCount(ctx, s.output) != 0)
        return ctx.error(sw + " output accessor " + std::to_string(s.output) + ": " +
                         std::to_string(accessorCount(ctx, s.output)) + " elements, expected " + std::to_string(expected) +
                         " (" + std::to_string(keys) + " keys" + (perKey > 1 ? " x " + std::to_string(perKey) + " targets" : "") +
                         (cubic ? " x 3 for CUBICSPLINE" : "") + ")");
      // Rotations and weights may be normalised integers (KHR_animation / glTF 2.0 allows it).
      const unsigned allowed = target == ChannelTarget::Rotation || target == ChannelTarget::Scalar
                                   ? kCompFloat | kCompByte | kCompUByte | kCompShort | kCompUShort
                                   : kCompFloat;
      if (std::string e = readFloatAccessor(ctx, s.output, components, allowed, sw + " output", out); !e.empty()) return e;
      if (m.accessors[s.output].componentType != TINYGLTF_COMPONENT_TYPE_FLOAT && !m.accessors[s.output].normalized)
        return ctx.error(sw + " output accessor " + std::to_string(s.output) + ": integer data must be normalized");

      const int joint = jointOfNode[ch.target_node];
      // Element e of the output as a value (x, y, z, w order as in glTF).
      auto element = [&](size_t e, size_t component0) {
        glm::vec4 v(0.0f);
        for (int i = 0; i < components; ++i) v[i] = out[e * components + i + component0];
        return v;
      };
      for (size_t t = 0; t < perKey; ++t) {
        Channel channel(joint, target, interpolation, times, {});
        if (target == ChannelTarget::Scalar) channel.property = "weights/" + std::to_string(t);
        channel.values.resize(keys);
        if (cubic) channel.keys.resize(keys);
        for (size_t k = 0; k < keys; ++k) {
          // CUBICSPLINE stores in-tangents, values, out-tangents per key, each perKey long.
          const size_t base = k * perKey * (cubic ? 3 : 1);
          if (!cubic) {
            channel.values[k] = element(base + t, 0);
            continue;
          }
          channel.values[k] = element(base + perKey + t, 0);
          KeySettings& ks = channel.keys[k];
          ks.interpolation = Interpolation::Hermite;
          ks.inTangent = element(base + t, 0);
          ks.outTangent = element(base + 2 * perKey + t, 0);
        }
        if (target == ChannelTarget::Rotation && !cubic)
          for (glm::vec4& q : channel.values) {
            if (q == glm::vec4(0.0f)) return ctx.error(sw + " output: key rotation is a zero quaternion");
            // Scaled by its largest component first: a plain length overflows beyond 1e19
            // (the fuzzer's keys of 1e36 became zero quaternions the .kinema reader refused).
            const glm::quat n = safeNormalize(glm::quat(q.w, q.x, q.y, q.z));
            q = glm::vec4(n.x, n.y, n.z, n.w);
          }
        clip.channels.push_back(std::move(channel));
      }
    }
    // The clip's frame rate: Kinema's own files keep it in the animation's extras (a clip
    // without it had none); a foreign file's keys give it when they lie on a grid; otherwise
    // it counts at the document's rate.
    if (anim.extras.IsObject() && anim.extras.Has("kinema_frame_time")) {
      const tinygltf::Value& v = anim.extras.Get("kinema_frame_time");
      const double frameTime = v.IsNumber() ? v.GetNumberAsDouble() : -1.0;
      if (std::isfinite(frameTime) && frameTime >= 1.0 / kMaxFrameRate && frameTime <= 1.0 / kMinFrameRate)
        clip.frameTime = frameTime;
      else
        ctx.warn("animation " + std::to_string(a) + ": extras.kinema_frame_time is not a frame time of " +
                 std::to_string(static_cast<int>(kMinFrameRate)) + " to " + std::to_string(static_cast<int>(kMaxFrameRate)) +
                 " fps: ignored");
    }
    if (clip.frameTime == 0.0 && !writtenByKinema) clip.frameTime = keyGridFrameTime(clip);
    scene.clips.push_back(std::move(clip));
  }
  return {};
}

}  // namespace kinema
