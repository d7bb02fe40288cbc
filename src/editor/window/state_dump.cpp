#include "editor/window/state_dump.h"

#include <nlohmann/json.hpp>

#include "editor/panels/compare_panel.h"
#include "editor/window/editor_window.h"
#include "editor/panels/panel_layout.h"
#include "editor/model/timeline.h"
#include "ik/ik_solver.h"

namespace kinema {

namespace {
using json = nlohmann::json;
json vec(const glm::vec3& v) { return json::array({v.x, v.y, v.z}); }
json jointName(const EditorState& s, int j) {
  return j >= 0 && j < s.doc.skeleton().size() ? json(s.doc.skeleton().names[j]) : json(nullptr);
}
// The timeline (timeline.h): frame, range, rate, playback switches, the ruler's pixels and
// the edited clip's channels with their key times.
json timelineJson(const EditorState& s) {
  const PanelRect strip = s.layout.timeline;
  const TimelineRuler r = timelineRuler(s, strip.x, strip.y, strip.w, strip.h);
  const AutoKeySettings& a = s.doc.autoKey;
  json t = {{"shown", s.timelineShown()},
            {"frame", currentFrame(s)},
            {"start", rangeStartFrame(s)},
            {"end", rangeEndFrame(s)},
            {"fps", timelineFps(s)},
            {"loop", s.loop},
            {"playing", s.playing},
            {"auto_key", a.enabled},
            {"key_interpolation", toString(a.preferences.interpolation)},
            {"key_handles", toString(a.preferences.handles)},
            {"animation_editor", s.animationEditor == AnimationEditorKind::DopeSheet     ? "dope-sheet"
                                 : s.animationEditor == AnimationEditorKind::CurveEditor ? "curve-editor"
                                                                                         : "none"},
            {"ruler", {{"x", r.x}, {"y", r.y}, {"width", r.w}, {"height", r.h}, {"first", r.first}, {"last", r.last},
                       {"margin", kTimelineRulerMargin}}}};
  json keyFrames = json::array();
  for (long long f : selectedKeyFrames(s)) keyFrames.push_back(f);
  t["selected_key_frames"] = keyFrames;
  json channels = json::array();
  if (s.hasMotion()) {
    const Clip& clip = s.doc.scene().clips[s.clip];
    t["clip_name"] = clip.name;
    for (const Channel& ch : clip.channels) {
      json times = json::array();
      for (float x : ch.times) times.push_back(x);
      json interpolations = json::array();
      for (int k = 0; k < ch.keyCount(); ++k) interpolations.push_back(toString(ch.settings(k).interpolation));
      channels.push_back({{"joint", jointName(s, ch.joint)},
                          {"target", toString(ch.target)},
                          {"times", times},
                          {"interpolations", interpolations}});
    }
  }
  t["channels"] = channels;
  // The foot contact strip (contact_lanes.h): the clip's contacts per foot, the selected one,
  // the strip's rectangle, and the bone map the clip keeps (its pair count and file).
  json contacts = {{"shown", s.bottomPanels().contactLanes}};
  if (s.hasMotion()) {
    const Clip& clip = s.doc.scene().clips[s.clip];
    for (int f = 0; f < 2; ++f) {
      json list = json::array();
      for (const ContactInterval& c : clip.contacts.feet[f]) list.push_back(json::array({c.first, c.last}));
      contacts[toString(static_cast<Foot>(f))] = list;
    }
    contacts["bone_map_pairs"] = clip.sourceMap.pairs.size();
    contacts["bone_map_file"] = clip.sourceMap.file;
    int keys = 0;
    for (const Channel& ch : clip.channels) keys += ch.keyCount();
    t["key_count"] = keys;
  }
  contacts["selected"] = {{"foot", toString(s.contactSelection.foot)}, {"index", s.contactSelection.index}};
  const PanelRect& lanes = s.layout.contactLanes;
  contacts["strip"] = {{"x", lanes.x}, {"y", lanes.y}, {"width", lanes.w}, {"height", lanes.h}};
  t["contacts"] = contacts;
  if (s.lastCleanUp) {
    const MotionCleanupReport& r = s.lastCleanUp->report;
    t["clean_up"] = {{"clip", s.lastCleanUp->clipName},     {"keys_before", r.keys.keysBefore},
                     {"keys_after", r.keys.keysAfter},      {"skate_before", r.skateBefore},
                     {"skate_after", r.skateAfter},         {"max_position_error", r.keys.maxPositionError},
                     {"max_degrees", r.keys.maxAngleError / 0.01745329251994329577}};
  }
  t["clean_up_window"] = s.cleanUpWindowOpen;
  return t;
}

// The curve editor: open or not, view, plot rectangle, the shown curves with their keys in
// display units (the e2e tests turn them into pixels), and the selected keys.
json curveEditorJson(const EditorState& s) {
  const CurveEditorState& ce = s.curveEditor;
  json out;
  out["open"] = s.animationEditor == AnimationEditorKind::CurveEditor;
  out["rotation_view"] = ce.rotationView == RotationView::Euler ? "euler" : "quaternion";
  out["euler_order"] = toString(ce.eulerOrder);
  out["normalized"] = ce.normalized;
  out["view"] = {{"t0", ce.view.t0}, {"t1", ce.view.t1}, {"v0", ce.view.v0}, {"v1", ce.view.v1}};
  out["plot"] = {{"x", ce.plot.x}, {"y", ce.plot.y}, {"width", ce.plot.w}, {"height", ce.plot.h}};
  json curves = json::array();
  if (s.hasMotion()) {
    const Clip& clip = s.doc.scene().clips[s.clip];
    for (int c : shownChannels(clip, s.doc.selection)) {
      const Channel& ch = clip.channels[c];
      for (int i = 0; i < curveCount(ch, ce.rotationView); ++i) {
        const CurvePoints p = curvePoints(ch, i, ce.rotationView, ce.eulerOrder);
        const ValueRange r = curveRange(p);
        json keys = json::array();
        for (size_t k = 0; k < p.keyTimes.size(); ++k) {
          const float v = ce.normalized ? normalizeValue(r, p.keyValues[k]) : p.keyValues[k];
          keys.push_back({{"time", p.keyTimes[k]}, {"value", p.keyValues[k]}, {"display", v},
                          {"interpolation", toString(ch.settings(int(k)).interpolation)}});
        }
        curves.push_back({{"channel", c},
                          {"component", i},
                          {"label", curveLabel(s.doc.skeleton(), ch, i, ce.rotationView, ce.eulerOrder)},
                          {"unit", displayUnitName(ch, ce.rotationView)},
                          {"visible", !ce.isHidden({c, i})},
                          {"value_now", curveValueAt(ch, i, ce.rotationView, ce.eulerOrder, p, float(s.time))},
                          {"modifiers", ch.modifiers.size()},
                          {"keys", keys}});
      }
    }
  }
  out["curves"] = curves;
  json selected = json::array();
  for (const CurveKeyRef& k : ce.selected) selected.push_back({{"channel", k.channel}, {"component", k.component}, {"key", k.key}});
  out["selected_keys"] = selected;
  out["box_armed"] = ce.boxArmed;
  return out;
}

// The dope sheet: shown or not, its view (key area in window pixels, frame at its left edge,
// pixels per frame, row height, scrolled rows), its rows with their key frames, the
// selected key columns and how many keys the clipboard holds.
json dopeSheetJson(const EditorState& s) {
  static const char* const kGestures[] = {"none", "press", "box", "drag_keys", "grab_keys", "pan"};
  const DopeSheetState& ds = s.dopeSheet;
  const DopeSheetView& v = ds.view;
  json out = {{"shown", s.animationEditor == AnimationEditorKind::DopeSheet},
              {"view", {{"x", v.x}, {"y", v.y}, {"width", v.width}, {"height", v.height}, {"first_frame", v.firstFrame},
                        {"pixels_per_frame", v.pixelsPerFrame}, {"row_height", v.rowHeight}, {"first_row", v.firstRow}}},
              {"clipboard_keys", ds.clipboard.keys.size()},
              {"gesture", kGestures[static_cast<int>(ds.gesture)]}};
  json rows = json::array(), selected = json::array();
  if (s.hasMotion()) {
    const Clip& clip = s.doc.scene().clips[s.clip];
    const FrameGrid grid = s.doc.scene().frameGrid(s.clip);
    for (const DopeSheetRow& r : dopeSheetRows(clip)) {
      json frames = json::array();
      for (float t : r.times) frames.push_back(grid.timeToFrame(t));
      rows.push_back({{"joint", r.joint < 0 ? json("Summary") : jointName(s, r.joint)}, {"frames", frames}});
    }
    for (const KeyColumn& c : ds.selection.columns())
      selected.push_back({{"joint", jointName(s, c.joint)}, {"frame", grid.timeToFrame(c.time)}});
  }
  out["rows"] = rows;
  out["selected"] = selected;
  return out;
}

json rect(const glm::vec4& r) { return json::array({r.x, r.y, r.z, r.w}); }

void addAnimationDisplayState(const EditorState& s, json& out) {
  const OnionSkinSettings& o = s.onionSkin;
  json ghosts = json::array();
  if (o.enabled && s.hasMotion()) {
    const Clip& clip = s.doc.scene().clips[s.clip];
    const FrameGrid grid = s.doc.scene().frameGrid(s.clip);
    for (const GhostFrame& g : ghostFrames(o, grid.nearestFrame(s.time), grid.nearestFrame(clip.duration()) + 1))
      ghosts.push_back({{"frame", g.frame}, {"offset", g.offset}, {"color", json::array({g.color.r, g.color.g, g.color.b, g.color.a})}});
  }
  out["onion_skin"] = {{"enabled", o.enabled}, {"before", o.before}, {"after", o.after}, {"step", o.step},
                       {"opacity", o.opacity}, {"ghosts", ghosts},
                       {"drawn_as", ghostsShowBodies(o, s.doc.scene()) ? "bodies" : "bones"}};
  out["motion_path"] = {{"enabled", s.motionPath.enabled}, {"whole_clip", s.motionPath.wholeClip}};
  const MotionControlSettings& m = s.motionControl;
  out["motion_control"] = {{"window_open", m.windowOpen}, {"profile", toString(m.profile)},
                           {"show_ticks", m.showTicks},
                           {"profile_rects", json::array({rect(m.profileRects[0]), rect(m.profileRects[1]), rect(m.profileRects[2])})},
                           {"apply_rect", rect(m.applyRect)}};
}
}  // namespace

std::string editorStateJson(const EditorState& s, int windowWidth, int windowHeight, long long frames) {
  json out;
  const Document& doc = s.doc;
  out["title"] = editorWindowTitle(s);
  out["path"] = doc.path();
  out["dirty"] = doc.dirty();
  out["undo_depth"] = doc.historyPosition();
  out["redo_depth"] = static_cast<int>(doc.historyLabels().size()) - doc.historyPosition();
  out["frames"] = frames;
  out["world_evaluations"] = doc.worldEvaluations();  // forward kinematics runs of this document (one per pose change)
  out["window"] = {{"width", windowWidth}, {"height", windowHeight}};
  // Edit > Preferences (user_preferences.h): the chosen UI scale; the font's pixel height
  // and the effective scale (times the monitor's content scale) as laid out this frame.
  out["ui_scale"] = s.preferences.uiScale;
  out["preferences"] = {{"ui_scale", s.preferences.uiScale},
                        {"line_scale", s.preferences.lineScale},
                        {"theme", toString(s.preferences.theme)},
                        {"font_size", s.layout.metrics.fontSize},
                        {"effective_scale", s.layout.metrics.scale},
                        {"panels",
                         {{"left_width", s.preferences.panels.leftWidth},
                          {"right_width", s.preferences.panels.rightWidth},
                          {"outliner_fraction", s.preferences.panels.outlinerFraction},
                          {"properties_fraction", s.preferences.panels.propertiesFraction},
                          {"animation_editor_height", s.preferences.panels.animationEditorHeight}}}};
  out["log"] = json::array();  // View > Log: every message in full, oldest first
  for (const LogEntry& e : s.log.entries()) out["log"].push_back({{"time", e.time}, {"text", e.text}, {"error", e.error}});
  out["viewport"] = {{"x", s.viewportRect.x}, {"y", s.viewportRect.y}, {"width", s.viewportRect.z},
                     {"height", s.viewportRect.w}};
  out["viewport_render"] = {{"samples", s.viewportRender.samples}, {"from_cache", s.viewportRender.fromCache}};
  out["window_redraw"] = {{"changed_only", s.windowRedraw.changedOnly},
                          {"kept_in", !s.windowRedraw.changedOnly ? "none"
                                      : s.windowRedraw.inBackBuffer ? "back_buffer"
                                                                    : "copy"},
                          {"rectangles", s.windowRedraw.rectangles},
                          {"pixels", s.windowRedraw.pixels},
                          {"presented", s.windowRedraw.presentedRectangles ? "rectangles" : "swap"}};
  out["playback"] = {{"clip", s.hasMotion() ? s.clip : -1}, {"time", s.time}, {"playing", s.playing}};
  json clipNames = json::array();  // the clip list in file order; playback.clip indexes it
  for (const Clip& c : doc.scene().clips) clipNames.push_back(c.name);
  out["clips"] = clipNames;
  out["timeline"] = timelineJson(s);
  {  // Simulate menu (issue 23): the dynamic parts, the live springs, the last bake
    json chains = json::array(), ragdolls = json::array();
    for (const SpringBoneChain& c : doc.scene().simulation.springChains) {
      json joints = json::array();
      for (int j : c.joints) joints.push_back(jointName(s, j));
      json colliders = json::array();
      for (const SpringCollider& k : c.colliders)
        colliders.push_back({{"joint", jointName(s, k.joint)}, {"a", vec(k.a)}, {"b", vec(k.b)}, {"radius", k.radius}});
      chains.push_back({{"name", c.name}, {"joints", joints}, {"stiffness", c.stiffness}, {"damping", c.damping},
                        {"colliders", colliders}});
    }
    for (const RagdollSettings& r : doc.scene().simulation.ragdolls)
      ragdolls.push_back({{"name", r.name}, {"root", jointName(s, r.root)}, {"start_frame", r.startFrame}});
    json sim = {{"spring_chains", chains}, {"ragdolls", ragdolls}, {"live", s.liveSprings.enabled},
                {"live_frames_simulated", s.liveSprings.context.dynamics.framesSimulated}, {"window", s.simulationWindowOpen},
                {"stiff_springs_window", s.stiffSpringsWindowOpen}};
    if (s.lastBake) {
      json parts = json::array();
      for (const SimulatedPart& p : s.lastBake->parts)
        parts.push_back({{"kind", p.kind}, {"name", p.name}, {"steps", p.steps}, {"largest_limit_excess", p.largestLimitExcess}});
      sim["last_bake"] = {{"parts", parts}, {"keys_before", s.lastBake->keysBefore}, {"keys_after", s.lastBake->keysAfter}};
    }
    out["simulation"] = sim;
  }
  {  // Simulate menu, crowds (issue 24): the settings in short, the live drawing
    json crowds = json::array();
    for (const CrowdSettings& c : doc.scene().simulation.crowds)
      crowds.push_back({{"name", c.name}, {"character", c.character}, {"members", c.members}, {"seed", c.seed},
                        {"allocation", c.boids.allocation == AccelerationAllocation::Priority ? "priority" : "average"},
                        {"spheres", c.boids.spheres.size()}, {"boxes", c.boids.boxes.size()}});
    const CrowdPreview& p = s.crowds.preview;
    json impulses = json::object();  // the debug member's desired accelerations at the frame shown (m/s^2)
    if (p.frame >= 0 && p.frame < static_cast<long long>(p.run.debug.size()))
      for (int k = 0; k < kBoidImpulseCount; ++k)
        impulses[toString(static_cast<BoidImpulse>(k))] = glm::length(p.run.debug[static_cast<size_t>(p.frame)].desired[k]);
    out["crowds"] = {{"crowds", crowds}, {"active", s.crowds.active}, {"window", s.crowds.windowOpen},
                     {"live", s.crowds.live}, {"runs", p.runs}, {"frame", p.frame},
                     {"members_drawn", p.world.size()}, {"debug_vectors", p.vectors.size()}, {"debug_impulses", impulses},
                     {"error", p.error}};
  }
  {  // Particle systems (issue 24): names, emitters, the live counts at the frame last shown
    json systems = json::array();
    for (size_t i = 0; i < doc.scene().simulation.particles.size(); ++i) {
      const ParticleSystemSettings& p = doc.scene().simulation.particles[i];
      json emitters = json::array();
      for (const ParticleEmitter& e : p.emitters)
        emitters.push_back({{"kind", toString(e.shape)}, {"joint", jointName(s, e.joint)}, {"rate", e.rate.mean}});
      json one = {{"name", p.name}, {"emitters", emitters}, {"restitution", p.forces.restitution}, {"size", p.size}};
      if (i < s.liveParticles.alive.size())
        one["alive"] = s.liveParticles.alive[i], one["emitted"] = s.liveParticles.emitted[i];
      systems.push_back(one);
    }
    out["particles"] = {{"systems", systems}, {"live", s.liveParticles.enabled}, {"frame", s.liveParticles.frame},
                        {"window", s.particlesWindowOpen}};
  }
  out["tool"] = modalToolName(s.tool.mode);
  {  // lattice edit mode (docs/cli.md): the edited lattice, its selected points where they are shown
    json lattice = {{"active", s.lattice.active}, {"moving", s.lattice.moving}};
    if (const Deformer* d = s.lattice.active ? editedLattice(s) : nullptr) {
      const std::vector<glm::vec3> points = latticeWorldPoints(s);
      json selected = json::array(), positions = json::array();
      for (int p : s.lattice.selected) {
        selected.push_back(p);
        positions.push_back({points[p].x, points[p].y, points[p].z});
      }
      lattice["instance"] = s.lattice.instance;
      lattice["deformer"] = d->name;
      lattice["points"] = d->lattice.pointCount();
      lattice["selected"] = selected;
      lattice["selected_positions"] = positions;  // world metres at the playhead
    }
    out["lattice_edit"] = lattice;
  }
  out["hovered_property"] = s.hoveredProperty.kind == HoveredProperty::Kind::ShapeWeight ? "shape"
                            : s.hoveredProperty.kind == HoveredProperty::Kind::DeformerParameter
                                ? "deformer:" + s.hoveredProperty.parameter
                                : "";
  out["compare"] = compareStateJson(s.compare);  // Teach > Compare Solvers (docs/cli.md)
  out["dope_sheet"] = dopeSheetJson(s);
  json selection = json::array();
  for (int j : doc.selection.joints()) selection.push_back(jointName(s, j));
  out["selection"] = selection;
  out["active"] = jointName(s, doc.selection.active());
  out["properties_joint"] = jointName(s, s.panels.propertiesJoint);  // the joint the properties panel showed
  out["hovered"] = jointName(s, s.hoveredJoint);
  out["auto_ik"] = s.view.autoIk;
  out["bones"] = !s.view.showBones ? "none" : s.view.xrayBones ? "x-ray" : "on";
  out["show_weights"] = s.view.showWeights;
  json skinning = json::array();
  for (const MeshInstance& m : doc.scene().meshInstances)
    skinning.push_back(m.skinning == SkinningMethod::DualQuaternion ? "dual-quaternion" : "linear");
  out["mesh_skinning"] = skinning;
  json skins = json::array();
  for (const MeshInstance& m : doc.scene().meshInstances) skins.push_back(m.skin);
  out["mesh_skins"] = skins;  // per mesh instance: its skin, -1 = not bound
  out["errors"] = s.panels.errors;  // waiting in the error popup, oldest first
  out["status"] = s.statusMessage;
  // Every named widget where it was last drawn (window pixels) and in which frame: scripts
  // click them by name ("item" events, docs/cli.md).
  json items = json::object();
  for (const auto& [name, r] : s.items.items)
    items[name] = {{"x", r.min.x}, {"y", r.min.y}, {"width", r.max.x - r.min.x}, {"height", r.max.y - r.min.y},
                   {"frame", r.frame}};
  out["items"] = items;
  const OrbitCamera& c = s.camera;
  out["camera"] = {{"azimuth", c.azimuthDeg},   {"elevation", c.elevationDeg}, {"distance", c.distance},
                   {"target", vec(c.target)},   {"fov_y", c.fovYDeg},          {"orthographic", c.orthographic},
                   {"eye", vec(c.eye())}};
  json joints = json::array();
  for (int j = 0; j < doc.skeleton().size(); ++j) {
    json e;
    e["name"] = doc.skeleton().names[j];
    e["parent"] = doc.skeleton().parents[j];
    if (j < doc.pose().size()) {
      const glm::quat& q = doc.pose().local[j].rotation;
      e["rotation"] = json::array({q.x, q.y, q.z, q.w});
      e["translation"] = vec(doc.pose().local[j].translation);
    }
    if (j < static_cast<int>(s.world().size())) e["world_position"] = vec(glm::vec3(s.world()[j][3]));
    joints.push_back(e);
  }
  out["joints"] = joints;
  json targets = json::array();
  for (size_t i = 0; i < doc.ikTargets().size(); ++i) {
    const IkTarget& t = doc.ikTargets()[i].target;
    const IkTarget resolved = doc.ikTargets()[i].resolved(doc.skeleton());
    json e = {{"effector", jointName(s, t.effector)},
              {"root", jointName(s, resolved.root)},
              {"solver", toString(doc.ikTargets()[i].solver)},
              {"chain_length", doc.ikTargets()[i].chainLength},
              {"pinned", doc.ikTargets()[i].pinned},
              {"position", vec(t.position)}};
    if (t.hasPole) e["pole"] = vec(t.pole);  // the two-bone pole target, when one is set
    for (const IkTargetReport& r : doc.lastIkReports())
      if (r.target == static_cast<int>(i)) {
        e["iterations"] = r.iterations;
        e["error"] = r.error;
        e["milliseconds"] = r.milliseconds;
        e["converged"] = r.converged;
      }
    targets.push_back(e);
  }
  out["ik_targets"] = targets;
  out["curve_editor"] = curveEditorJson(s);
  out["popup_open"] = s.panels.popupOpen;  // a menu, combo or popup (not a modal) is open
  out["help_window"] = s.panels.showHelp;  // Help > Controls
  addAnimationDisplayState(s, out);  // onion skin, motion path, motion control
  return out.dump(1) + "\n";
}

}  // namespace kinema
