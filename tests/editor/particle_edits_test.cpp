// The editor's particle systems without a window (issue 24): adding an emitter on the active
// joint, editing and removing it are one undo step each and mark the document changed (so
// a save asks); the live particles follow the clip's joint and restart after an edit.
#include <gtest/gtest.h>

#include "core/default_character.h"
#include "core/forward_kinematics.h"
#include "editor/model/document.h"
#include "editor/model/particle_edits.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

// The default character whose hips slide 1 m along +x over 1 s at 30 fps.
Scene sliding() {
  Scene scene;
  scene.skeleton = makeDefaultCharacter();
  const int hips = scene.skeleton.find("Hips");
  const glm::vec3 rest = scene.skeleton.rest[hips].translation;
  Clip clip;
  clip.name = "slide";
  clip.frameTime = 1.0 / 30.0;
  clip.channels.emplace_back(hips, ChannelTarget::Translation, Interpolation::Linear, std::vector<float>{0.0f, 1.0f},
                             std::vector<glm::vec4>{glm::vec4(rest, 0.0f), glm::vec4(rest + glm::vec3(1, 0, 0), 0.0f)});
  scene.clips.push_back(clip);
  return scene;
}

TEST(ParticleEdits, AddSetRemoveAreOneUndoStepEachAndMakeTheDocumentDirty) {
  Document doc(sliding());
  const int hand = doc.skeleton().find("Hand.R");
  ASSERT_GE(hand, 0);
  EXPECT_FALSE(doc.dirty());
  int index = -1;
  ASSERT_EQ(addParticleEmitterEdit(doc, hand, &index), "");
  EXPECT_EQ(index, 0);
  EXPECT_TRUE(doc.dirty()) << "document change detection sees the new system";
  const ParticleSystemSettings added = doc.scene().simulation.particles.at(0);
  EXPECT_EQ(added.emitters.at(0).shape, EmitterShape::Joint);
  EXPECT_EQ(added.emitters[0].joint, hand);
  EXPECT_EQ(added.name, "Hand.R sparks");
  EXPECT_TRUE(doc.sceneForSaving().simulation.particles.at(0) == added) << "saved with the file";
  // A second one at the origin gets its own name.
  ASSERT_EQ(addParticleEmitterEdit(doc, -1), "");
  EXPECT_EQ(doc.scene().simulation.particles.at(1).emitters[0].shape, EmitterShape::Point);
  EXPECT_EQ(doc.scene().simulation.particles.at(1).name, "fountain");

  ParticleSystemSettings changed = added;
  changed.forces.restitution = 0.9f;
  ASSERT_EQ(setParticleSystemEdit(doc, 0, changed), "");
  EXPECT_EQ(doc.scene().simulation.particles[0].forces.restitution, 0.9f);
  ASSERT_EQ(removeParticleSystemEdit(doc, 1), "");
  EXPECT_EQ(doc.historyLabels(), (std::vector<std::string>{"Add particle emitter", "Add particle emitter",
                                                            "Set particle system Hand.R sparks",
                                                            "Remove particle system fountain"}));
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(doc.scene().simulation.particles.size(), 2u);
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(doc.scene().simulation.particles[0].forces.restitution, added.forces.restitution) << "the edit undone";
  ASSERT_TRUE(doc.undo());
  ASSERT_TRUE(doc.undo());
  EXPECT_TRUE(doc.scene().simulation.particles.empty());
  EXPECT_FALSE(doc.dirty()) << "back to the saved state";
  // Settings that do not fit are refused whole, with no undo step.
  ASSERT_TRUE(doc.redo());
  ParticleSystemSettings bad = added;
  bad.forces.restitution = 2.0f;
  EXPECT_NE(setParticleSystemEdit(doc, 0, bad), "");
  EXPECT_TRUE(doc.scene().simulation.particles[0] == added);
  EXPECT_EQ(doc.historyPosition(), 1);
}

TEST(ParticleEdits, LiveParticlesAreBornAtTheClipsJointAndRestartAfterAnEdit) {
  Document doc(sliding());
  const int hips = doc.skeleton().find("Hips");
  ASSERT_EQ(addParticleEmitterEdit(doc, hips), "");
  ParticleSystemSettings s = doc.scene().simulation.particles[0];
  s.emitters[0].rate = {30.0f, 0.0f, RandomDistribution::Uniform};  // one a frame
  s.emitters[0].speed = {0.0f, 0.0f, RandomDistribution::Uniform};
  s.emitters[0].lifetime = {100.0f, 0.0f, RandomDistribution::Uniform};
  s.forces.gravity = glm::vec3(0.0f);
  ASSERT_EQ(setParticleSystemEdit(doc, 0, s), "");
  LiveParticles live;
  const std::vector<ParticleState>* states = liveParticlesAt(live, doc, 0, 15);
  ASSERT_NE(states, nullptr);
  ASSERT_EQ(states->at(0).size(), 15);
  EXPECT_EQ(live.alive, std::vector<int>{15});
  // Particle k was born at frame k + 1, where the clip had moved the hips (k + 1) / 30 m.
  const glm::vec3 rest(computeWorld(doc.skeleton(), Pose::rest(doc.skeleton()))[hips][3]);
  for (int k = 0; k < 15; ++k) EXPECT_NEAR(states->at(0).positions[k].x, rest.x + (k + 1) / 30.0f, 1e-4f) << k;
  const long long steps = live.playback.stepsRun();
  liveParticlesAt(live, doc, 0, 16);
  EXPECT_EQ(live.playback.stepsRun(), steps + 1) << "playing on steps once";
  s.forces.drag = 1.0f;
  ASSERT_EQ(setParticleSystemEdit(doc, 0, s), "");
  liveParticlesAt(live, doc, 0, 16);
  EXPECT_EQ(live.playback.stepsRun(), steps + 1 + 16) << "an edit simulates again from frame 0";
  live.enabled = false;
  EXPECT_EQ(liveParticlesAt(live, doc, 0, 16), nullptr);
}

}  // namespace
}  // namespace kinema
