#pragma once
// An OpenCASCADE shape (faces, shells or solids of a blade) behind an opaque handle, so that
// users of the module never include OCCT headers. Coordinates are in mm in the workpiece frame
// W (x = the rotary axis A). Copies share the same immutable shape.

#include "core/geometry/vec.h"

#include <memory>

namespace bladeaxis::cad {

struct BoundingBox {
    Vec3 min = Vec3::Zero();
    Vec3 max = Vec3::Zero();
};

class CadShape {
  public:
    struct Impl; // defined in core/cad/detail/occt_shape.h
    CadShape() = default;
    explicit CadShape(std::shared_ptr<const Impl> impl) : m_impl(std::move(impl)) {}

    bool isNull() const { return m_impl == nullptr; }
    int faceCount() const;
    // Tight axis-aligned box around the geometry (computed on the surfaces, so not free).
    BoundingBox bounds() const;

    const Impl& impl() const { return *m_impl; }

  private:
    std::shared_ptr<const Impl> m_impl;
};

} // namespace bladeaxis::cad
