#include "editor/window/imgui_damage.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>

namespace kinema {
namespace {

// A list as drawn: per index position, the command that draws it.
struct Drawn {
  const ImDrawVert* vertices = nullptr;
  const ImDrawIdx* indices = nullptr;
  const ImDrawCmd* commands = nullptr;
  size_t vertexCount = 0, indexCount = 0, commandCount = 0;
  std::vector<unsigned int> commandOf;  // index position -> command; ~0u past ElemCount coverage

  void index() {
    commandOf.assign(indexCount, ~0u);
    for (size_t c = 0; c < commandCount; ++c) {
      const ImDrawCmd& cmd = commands[c];
      const size_t end = std::min<size_t>(indexCount, size_t(cmd.IdxOffset) + cmd.ElemCount);
      for (size_t k = cmd.IdxOffset; k < end; ++k) commandOf[k] = static_cast<unsigned int>(c);
    }
  }
  const ImDrawCmd* command(size_t k) const { return commandOf[k] == ~0u ? nullptr : &commands[commandOf[k]]; }
  const ImDrawVert* vertex(size_t k) const {
    const ImDrawCmd* c = command(k);
    const size_t v = (c ? c->VtxOffset : 0) + indices[k];
    return v < vertexCount ? &vertices[v] : nullptr;
  }
};

bool sameCommand(const ImDrawCmd* a, const ImDrawCmd* b) {
  if (!a || !b) return a == b;
  return std::memcmp(&a->ClipRect, &b->ClipRect, sizeof(ImVec4)) == 0 && a->TextureId == b->TextureId &&
         a->UserCallback == nullptr && b->UserCallback == nullptr;
}

bool sameAt(const Drawn& a, size_t ka, const Drawn& b, size_t kb, ImTextureID font) {
  const ImDrawCmd* ca = a.command(ka);
  const ImDrawCmd* cb = b.command(kb);
  if (!sameCommand(ca, cb) || (ca && ca->TextureId != font)) return false;
  const ImDrawVert* va = a.vertex(ka);
  const ImDrawVert* vb = b.vertex(kb);
  return va && vb && std::memcmp(va, vb, sizeof(ImDrawVert)) == 0;
}

struct Box {
  float minX = std::numeric_limits<float>::max(), minY = minX;
  float maxX = -std::numeric_limits<float>::max(), maxY = maxX;
  bool whole = false;
  // The triangle starting at index position k, clipped to its command's rectangle.
  void addTriangle(const Drawn& d, size_t k) {
    const ImDrawCmd* c = d.command(k);
    if (!c) return;  // not drawn
    if (c->UserCallback) {
      whole = true;
      return;
    }
    float x0 = std::numeric_limits<float>::max(), y0 = x0, x1 = -x0, y1 = -x0;
    for (size_t i = k; i < k + 3 && i < d.indexCount; ++i)
      if (const ImDrawVert* v = d.vertex(i)) {
        x0 = std::min(x0, v->pos.x), y0 = std::min(y0, v->pos.y);
        x1 = std::max(x1, v->pos.x), y1 = std::max(y1, v->pos.y);
      }
    x0 = std::max(x0, c->ClipRect.x), y0 = std::max(y0, c->ClipRect.y);
    x1 = std::min(x1, c->ClipRect.z), y1 = std::min(y1, c->ClipRect.w);
    if (x1 <= x0 || y1 <= y0) return;
    minX = std::min(minX, x0), minY = std::min(minY, y0), maxX = std::max(maxX, x1), maxY = std::max(maxY, y1);
  }
};

Drawn drawnOf(const ImDrawList& l) {
  Drawn d;
  d.vertices = l.VtxBuffer.Data, d.vertexCount = size_t(l.VtxBuffer.Size);
  d.indices = l.IdxBuffer.Data, d.indexCount = size_t(l.IdxBuffer.Size);
  d.commands = l.CmdBuffer.Data, d.commandCount = size_t(l.CmdBuffer.Size);
  d.index();
  return d;
}
Drawn drawnOf(const ImGuiDrawSnapshot::List& l) {
  Drawn d;
  d.vertices = l.vertices.data(), d.vertexCount = l.vertices.size();
  d.indices = l.indices.data(), d.indexCount = l.indices.size();
  d.commands = l.commands.data(), d.commandCount = l.commands.size();
  d.index();
  return d;
}

// Boxes of changed triangles, joined when they come within kJoin pixels of each other: a
// moved playhead and a changed frame number far from it stay two small rectangles.
constexpr float kJoin = 16.0f;
bool near(const Box& a, const Box& b) {
  return a.minX <= b.maxX + kJoin && a.maxX >= b.minX - kJoin && a.minY <= b.maxY + kJoin && a.maxY >= b.minY - kJoin;
}
void join(Box& into, const Box& b) {
  into.minX = std::min(into.minX, b.minX), into.minY = std::min(into.minY, b.minY);
  into.maxX = std::max(into.maxX, b.maxX), into.maxY = std::max(into.maxY, b.maxY);
}
// At most kMostBoxes a window (the damage is merged to four rectangles later anyway): past
// that, a box joins the one whose centre is nearest, so the work stays linear.
constexpr size_t kMostBoxes = 16;
void addToNearest(std::vector<Box>& boxes, const Box& t) {
  if (t.minX > t.maxX) return;
  for (Box& b : boxes)
    if (near(b, t)) return join(b, t);
  if (boxes.size() < kMostBoxes) return boxes.push_back(t);
  auto centreDistance = [&t](const Box& b) {
    return std::abs(b.minX + b.maxX - t.minX - t.maxX) + std::abs(b.minY + b.maxY - t.minY - t.maxY);
  };
  join(*std::min_element(boxes.begin(), boxes.end(),
                         [&](const Box& x, const Box& y) { return centreDistance(x) < centreDistance(y); }),
       t);
}

// The changed triangles of one window's list between two frames, as boxes (`whole` set on
// the first for a user callback). Between the triangles alike at the start and at the end,
// two runs of the same length (the same widgets, some with other values or places) are
// compared triangle by triangle, so only those that differ count; runs of other lengths
// count whole.
std::vector<Box> compareList(const Drawn& a, const Drawn& b, ImTextureID font) {
  const size_t na = a.indexCount - a.indexCount % 3, nb = b.indexCount - b.indexCount % 3;
  size_t prefix = 0;
  while (prefix < na && prefix < nb && sameAt(a, prefix, b, prefix, font)) ++prefix;
  prefix -= prefix % 3;
  size_t suffix = 0;
  while (suffix < na - prefix && suffix < nb - prefix && sameAt(a, na - 1 - suffix, b, nb - 1 - suffix, font)) ++suffix;
  suffix -= suffix % 3;
  std::vector<Box> boxes;
  bool whole = false;
  auto add = [&](const Drawn& d, size_t k) {
    Box t;
    t.addTriangle(d, k);
    whole = whole || t.whole;
    addToNearest(boxes, t);
  };
  if (na - suffix - prefix == nb - suffix - prefix) {
    for (size_t k = prefix; k < na - suffix; k += 3)
      if (!sameAt(a, k, b, k, font) || !sameAt(a, k + 1, b, k + 1, font) || !sameAt(a, k + 2, b, k + 2, font))
        add(a, k), add(b, k);
  } else {
    for (size_t k = prefix; k < na - suffix; k += 3) add(a, k);
    for (size_t k = prefix; k < nb - suffix; k += 3) add(b, k);
  }
  // A box grown by joining may now come near another: join until none does.
  for (bool joined = true; joined;) {
    joined = false;
    for (size_t i = 0; i < boxes.size(); ++i)
      for (size_t j = i + 1; j < boxes.size();) {
        if (near(boxes[i], boxes[j])) {
          join(boxes[i], boxes[j]);
          boxes.erase(boxes.begin() + static_cast<std::ptrdiff_t>(j));
          joined = true;
        } else {
          ++j;
        }
      }
  }
  if (whole) {
    boxes.assign(1, Box());
    boxes[0].whole = true;
  }
  return boxes;
}

// The common case, found without indexing either list: a window drawn exactly as before, its
// commands all plain font draws (what compareList would find no changed triangle in).
bool drawnAlike(const ImGuiDrawSnapshot::List& a, const ImDrawList& b, ImTextureID font) {
  if (a.vertices.size() != size_t(b.VtxBuffer.Size) || a.indices.size() != size_t(b.IdxBuffer.Size) ||
      a.commands.size() != size_t(b.CmdBuffer.Size))
    return false;
  for (size_t c = 0; c < a.commands.size(); ++c) {
    const ImDrawCmd& ca = a.commands[c];
    const ImDrawCmd& cb = b.CmdBuffer.Data[c];
    if (!sameCommand(&ca, &cb) || ca.TextureId != font || ca.VtxOffset != cb.VtxOffset ||
        ca.IdxOffset != cb.IdxOffset || ca.ElemCount != cb.ElemCount)
      return false;
  }
  return std::memcmp(a.indices.data(), b.IdxBuffer.Data, a.indices.size() * sizeof(ImDrawIdx)) == 0 &&
         std::memcmp(a.vertices.data(), b.VtxBuffer.Data, a.vertices.size() * sizeof(ImDrawVert)) == 0;
}

void copyInto(ImGuiDrawSnapshot::List& c, const ImDrawList& l) {  // keeps c's capacity
  c.owner = l._OwnerName ? l._OwnerName : "";
  c.vertices.assign(l.VtxBuffer.Data, l.VtxBuffer.Data + l.VtxBuffer.Size);
  c.indices.assign(l.IdxBuffer.Data, l.IdxBuffer.Data + l.IdxBuffer.Size);
  c.commands.assign(l.CmdBuffer.Data, l.CmdBuffer.Data + l.CmdBuffer.Size);
}

}  // namespace

std::vector<PixelRect> imguiDamage(const ImDrawData& now, ImTextureID fontTexture, ImGuiDrawSnapshot& last) {
  const PixelRect display{static_cast<int>(std::floor(now.DisplayPos.x)), static_cast<int>(std::floor(now.DisplayPos.y)),
                          static_cast<int>(std::ceil(now.DisplayPos.x + now.DisplaySize.x)),
                          static_cast<int>(std::ceil(now.DisplayPos.y + now.DisplaySize.y))};
  bool whole = !last.valid || last.fontTexture != fontTexture || last.displayPos.x != now.DisplayPos.x ||
               last.displayPos.y != now.DisplayPos.y || last.displaySize.x != now.DisplaySize.x ||
               last.displaySize.y != now.DisplaySize.y || static_cast<int>(last.lists.size()) != now.CmdListsCount;
  for (int n = 0; n < now.CmdListsCount && !whole; ++n) {
    const char* owner = now.CmdLists[n]->_OwnerName;
    whole = last.lists[size_t(n)].owner != (owner ? owner : "");
  }
  std::vector<PixelRect> out;
  if (!whole) {
    for (int n = 0; n < now.CmdListsCount && !whole; ++n) {
      if (drawnAlike(last.lists[size_t(n)], *now.CmdLists[n], fontTexture)) continue;
      for (const Box& box : compareList(drawnOf(last.lists[size_t(n)]), drawnOf(*now.CmdLists[n]), fontTexture)) {
        whole = whole || box.whole;
        // Antialiased edges stay inside their vertices; one pixel more covers rounding.
        if (box.minX <= box.maxX) out.push_back(PixelRect::covering(box.minX, box.minY, box.maxX, box.maxY, display).grown(1));
      }
    }
  }
  if (whole) out.assign(1, display);
  for (PixelRect& r : out) r = r.intersected(display);
  out.erase(std::remove_if(out.begin(), out.end(), [](const PixelRect& r) { return r.empty(); }), out.end());
  last.valid = true;
  last.displayPos = now.DisplayPos;
  last.displaySize = now.DisplaySize;
  last.fontTexture = fontTexture;
  last.lists.resize(static_cast<size_t>(std::max(now.CmdListsCount, 0)));
  for (int n = 0; n < now.CmdListsCount; ++n) copyInto(last.lists[size_t(n)], *now.CmdLists[n]);
  return out;
}

}  // namespace kinema
