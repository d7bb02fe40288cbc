#include "io/gltf_accessor.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "io/gltf_import_parts.h"
#include "io/gltf_limits.h"

namespace kinema {

void GltfContext::warn(const std::string& what) {
  if (std::find(warnings.begin(), warnings.end(), what) == warnings.end()) warnings.push_back(what);
}

namespace {

unsigned maskOf(int componentType) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return kCompByte;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return kCompUByte;
    case TINYGLTF_COMPONENT_TYPE_SHORT: return kCompShort;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return kCompUShort;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return kCompUInt;
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return kCompFloat;
    default: return 0;
  }
}

size_t componentSize(int componentType) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;
  }
}

int componentsOf(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    case TINYGLTF_TYPE_MAT2: return 4 + 100;  // distinct from VEC4: matrices are only MAT4 here
    case TINYGLTF_TYPE_MAT3: return 9;
    case TINYGLTF_TYPE_MAT4: return 16;
    default: return 0;
  }
}

const char* typeName(int components) {
  switch (components) {
    case 1: return "SCALAR";
    case 2: return "VEC2";
    case 3: return "VEC3";
    case 4: return "VEC4";
    case 16: return "MAT4";
    default: return "?";
  }
}

std::string componentNames(unsigned mask) {
  static const struct {
    unsigned bit;
    const char* name;
  } names[] = {{kCompFloat, "FLOAT"},         {kCompUByte, "UNSIGNED_BYTE"}, {kCompUShort, "UNSIGNED_SHORT"},
               {kCompUInt, "UNSIGNED_INT"},   {kCompByte, "BYTE"},           {kCompShort, "SHORT"}};
  std::string s;
  for (const auto& n : names)
    if (mask & n.bit) s += (s.empty() ? "" : " or ") + std::string(n.name);
  return s;
}

// One component as a double: integers exactly, normalised integers mapped as glTF says.
double component(const uint8_t* p, int componentType, bool normalized) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      int8_t v;
      std::memcpy(&v, p, 1);
      return normalized ? std::max(v / 127.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
      uint8_t v;
      std::memcpy(&v, p, 1);
      return normalized ? v / 255.0 : v;
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      int16_t v;
      std::memcpy(&v, p, 2);
      return normalized ? std::max(v / 32767.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      uint16_t v;
      std::memcpy(&v, p, 2);
      return normalized ? v / 65535.0 : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
      uint32_t v;
      std::memcpy(&v, p, 4);
      return v;
    }
    default: {
      float v;
      std::memcpy(&v, p, 4);
      return v;
    }
  }
}

// A validated byte range of a bufferView: `length` bytes starting at `data`.
struct ViewBytes {
  const uint8_t* data = nullptr;
  size_t length = 0;
  size_t stride = 0;  // the bufferView's byteStride, 0 when tightly packed
};

std::string viewBytes(const GltfContext& ctx, int view, const std::string& where, ViewBytes& out) {
  const tinygltf::Model& m = ctx.model;
  if (view < 0 || static_cast<size_t>(view) >= m.bufferViews.size())
    return ctx.error(where + ": bufferView " + std::to_string(view) + " does not exist (the file has " +
                     std::to_string(m.bufferViews.size()) + ")");
  const tinygltf::BufferView& bv = m.bufferViews[view];
  const std::string bvName = where + ": bufferView " + std::to_string(view);
  if (bv.buffer < 0 || static_cast<size_t>(bv.buffer) >= m.buffers.size())
    return ctx.error(bvName + ": buffer " + std::to_string(bv.buffer) + " does not exist");
  const size_t size = m.buffers[bv.buffer].data.size();
  if (bv.byteOffset > size || bv.byteLength > size - bv.byteOffset)
    return ctx.error(bvName + ": bytes " + std::to_string(bv.byteOffset) + " + " + std::to_string(bv.byteLength) +
                     " lie past the end of buffer " + std::to_string(bv.buffer) + " (" + std::to_string(size) +
                     " bytes)");
  out.data = m.buffers[bv.buffer].data.data() + bv.byteOffset;
  out.length = bv.byteLength;
  out.stride = bv.byteStride;
  return {};
}

// Checks accessor `index` and decodes it into doubles, count * components of them.
std::string decode(GltfContext& ctx, int index, int components, unsigned allowed, bool integers,
                   const std::string& use, std::vector<double>& out) {
  const tinygltf::Model& m = ctx.model;
  const std::string where = use + " accessor " + std::to_string(index);
  if (index < 0 || static_cast<size_t>(index) >= m.accessors.size())
    return ctx.error(use + ": accessor " + std::to_string(index) + " does not exist (the file has " +
                     std::to_string(m.accessors.size()) + ")");
  const tinygltf::Accessor& a = m.accessors[index];
  if (componentsOf(a.type) != components)
    return ctx.error(where + ": expected type " + typeName(components));
  const unsigned mask = maskOf(a.componentType);
  if (!(mask & allowed))
    return ctx.error(where + ": componentType " + std::to_string(a.componentType) + " is not " +
                     componentNames(allowed));
  if (integers && a.normalized) return ctx.error(where + ": integer data must not be normalized");
  if (a.normalized && mask == kCompFloat) return ctx.error(where + ": FLOAT data cannot be normalized");
  if (a.count < 1) return ctx.error(where + ": count must be at least 1");
  if (a.count > GltfLimits::kMaxAccessorElements)
    return ctx.error(where + ": " + std::to_string(a.count) + " elements exceed the limit of " +
                     std::to_string(GltfLimits::kMaxAccessorElements));
  const size_t values = a.count * static_cast<size_t>(components);
  if (values > GltfLimits::kMaxDecodedValues - ctx.decodedValues)
    return ctx.error(where + ": the file decodes to more than " + std::to_string(GltfLimits::kMaxDecodedValues) +
                     " numbers (the limit)");
  const size_t csize = componentSize(a.componentType);
  const size_t elementSize = csize * components;

  // Dense part: zeros without a bufferView (sparse accessors may omit it).
  ViewBytes view;
  if (a.bufferView >= 0) {
    if (std::string e = viewBytes(ctx, a.bufferView, where, view); !e.empty()) return e;
    const size_t stride = view.stride ? view.stride : elementSize;
    if (view.stride && (view.stride < elementSize || view.stride % csize != 0 || view.stride > 252))
      return ctx.error(where + ": bufferView " + std::to_string(a.bufferView) + " byteStride " +
                       std::to_string(view.stride) + " does not fit elements of " + std::to_string(elementSize) +
                       " bytes");
    // No overflow: byteOffset is checked first and count is capped.
    const size_t last = a.byteOffset > view.length ? 0 : a.byteOffset + stride * (a.count - 1) + elementSize;
    if (a.byteOffset > view.length || last > view.length)
      return ctx.error(where + ": byteOffset " + std::to_string(a.byteOffset) + " + " + std::to_string(a.count) +
                       " elements of stride " + std::to_string(stride) + " need " + std::to_string(last) +
                       " bytes but bufferView " + std::to_string(a.bufferView) + " has " +
                       std::to_string(view.length));
    view.stride = stride;
  } else if (!a.sparse.isSparse) {
    ctx.warn("accessor " + std::to_string(index) + " has no bufferView: read as zeros");
  }
  ctx.decodedValues += values;
  out.assign(values, 0.0);
  if (view.data)
    for (size_t e = 0; e < a.count; ++e) {
      const uint8_t* p = view.data + a.byteOffset + e * view.stride;
      for (int c = 0; c < components; ++c) out[e * components + c] = component(p + c * csize, a.componentType, a.normalized);
    }

  if (a.sparse.isSparse) {
    const std::string sw = where + " sparse";
    const int n = a.sparse.count;
    if (n < 1 || static_cast<size_t>(n) > a.count)
      return ctx.error(sw + ": count " + std::to_string(n) + " must be 1 to the accessor's count " +
                       std::to_string(a.count));
    const int ict = a.sparse.indices.componentType;
    const unsigned imask = maskOf(ict);
    if (!(imask & (kCompUByte | kCompUShort | kCompUInt)))
      return ctx.error(sw + ": indices componentType " + std::to_string(ict) +
                       " is not UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT");
    ViewBytes iv, vv;
    if (std::string e = viewBytes(ctx, a.sparse.indices.bufferView, sw + " indices", iv); !e.empty()) return e;
    if (std::string e = viewBytes(ctx, a.sparse.values.bufferView, sw + " values", vv); !e.empty()) return e;
    const size_t isize = componentSize(ict);
    if (a.sparse.indices.byteOffset < 0 || a.sparse.values.byteOffset < 0 ||
        static_cast<size_t>(a.sparse.indices.byteOffset) + isize * n > iv.length ||
        static_cast<size_t>(a.sparse.values.byteOffset) + elementSize * n > vv.length)
      return ctx.error(sw + ": " + std::to_string(n) + " indices or values lie past the end of their bufferView");
    const uint8_t* ip = iv.data + a.sparse.indices.byteOffset;
    const uint8_t* vp = vv.data + a.sparse.values.byteOffset;
    double previous = -1;
    for (int k = 0; k < n; ++k) {
      const double target = component(ip + k * isize, ict, false);
      if (target >= static_cast<double>(a.count) || target <= previous)
        return ctx.error(sw + ": index " + std::to_string(static_cast<uint64_t>(target)) + " at " +
                         std::to_string(k) + " is out of range or not increasing (count " + std::to_string(a.count) +
                         ")");
      previous = target;
      const size_t e = static_cast<size_t>(target);
      for (int c = 0; c < components; ++c)
        out[e * components + c] = component(vp + k * elementSize + c * csize, a.componentType, a.normalized);
    }
  }
  if (mask == kCompFloat)
    for (size_t i = 0; i < out.size(); ++i)
      if (!std::isfinite(out[i]))
        return ctx.error(where + ": element " + std::to_string(i / components) + " is not a finite number");
  return {};
}

}  // namespace

size_t accessorCount(const GltfContext& ctx, int index) {
  if (index < 0 || static_cast<size_t>(index) >= ctx.model.accessors.size()) return 0;
  return ctx.model.accessors[index].count;
}

std::string readFloatAccessor(GltfContext& ctx, int index, int components, unsigned allowed, const std::string& use,
                              std::vector<float>& out) {
  std::vector<double> values;
  if (std::string e = decode(ctx, index, components, allowed, false, use, values); !e.empty()) return e;
  out.resize(values.size());
  for (size_t i = 0; i < values.size(); ++i) {
    out[i] = static_cast<float>(values[i]);
    if (!std::isfinite(out[i]))  // a finite double beyond float range
      return ctx.error(use + " accessor " + std::to_string(index) + ": element " + std::to_string(i / components) +
                       " is out of float range");
  }
  return {};
}

std::string readUintAccessor(GltfContext& ctx, int index, int components, unsigned allowed, const std::string& use,
                             std::vector<uint32_t>& out) {
  std::vector<double> values;
  if (std::string e = decode(ctx, index, components, allowed & (kCompUByte | kCompUShort | kCompUInt), true, use, values);
      !e.empty())
    return e;
  out.resize(values.size());
  for (size_t i = 0; i < values.size(); ++i) out[i] = static_cast<uint32_t>(values[i]);
  return {};
}

}  // namespace kinema

namespace kinema {

std::string bufferViewBytes(const GltfContext& ctx, int view, const std::string& use, const unsigned char*& data,
                            size_t& length) {
  ViewBytes bytes;
  if (std::string e = viewBytes(ctx, view, use, bytes); !e.empty()) return e;
  data = bytes.data;
  length = bytes.length;
  return {};
}

}  // namespace kinema
