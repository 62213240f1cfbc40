#pragma once
// STEP (ISO 10303-21, AP214) and IGES files of blade geometry.
//
// Writing: the shape in mm is written in the requested file unit (OpenCASCADE scales the
// coordinates); outputs are written to a temporary sibling and renamed into place.
// Reading: faces, shells and solids are transferred (curves and points alone are refused),
// coordinates are converted from the file's unit to mm, then the caller's placement puts the
// blade relative to the rotary axis. Every failure is a Result error naming the file and what
// was expected; OpenCASCADE exceptions never escape. OpenCASCADE 7.6 crashes (SIGSEGV) on some
// malformed STEP files, so the translation runs in a forked child process that hands the shape
// back as a binary BRep file; a crash, an exception or a hang (5 min) of the child is reported as
// a Parse error. Reads and writes are serialised (OpenCASCADE keeps its data-exchange settings in
// process-wide state).

#include "core/base/error.h"
#include "core/cad/cad_shape.h"
#include "core/geometry/vec.h"

#include <cstddef>
#include <filesystem>

namespace bladeaxis::cad {

enum class CadFormat { Step, Iges };

enum class LengthUnit { Millimetre, Inch, Metre };

// Rigid placement of the file's geometry in W: p_W = rotation * p_file + translation (mm).
// The rotation must be orthonormal with determinant +1.
struct Placement {
    Mat3 rotation = Mat3::Identity();
    Vec3 translation = Vec3::Zero();
};

// A placement as users state it (command line, job file, GUI): rotations about the fixed X, Y and
// Z axes of W, in that order, then the translation: p_W = Rz(c) Ry(b) Rx(a) p_file + t. Angles in
// rad, so the edges convert degrees once; kept as angles so a saved job writes back what was
// given instead of a decomposed matrix.
struct AxisRotationPlacement {
    Vec3 rotationXyz = Vec3::Zero(); // rad: (a, b, c) about X, Y, Z
    Vec3 translation = Vec3::Zero(); // mm
};

Placement toPlacement(const AxisRotationPlacement& placement);

// The shape moved rigidly: p' = rotation * p + translation. Errors: InvalidArgument (an empty
// shape, or a placement that is not a rotation), Geometry (OpenCASCADE failed).
Result<CadShape> placedShape(const CadShape& shape, const Placement& placement);

// Errors: InvalidArgument (null or face-less shape), WriteFailed.
Status writeCadFile(const CadShape& shape, const std::filesystem::path& path, CadFormat format,
                    LengthUnit unit = LengthUnit::Millimetre);

// The format from the content ("ISO-10303-21;" header, or the IGES start/global section columns),
// falling back to the extension (.step .stp .iges .igs); Parse error when neither tells.
Result<CadFormat> detectCadFormat(const std::filesystem::path& path);

// A blade model has tens to thousands of faces; a file with more is an assembly, a fixture or a
// meshed scan, whose every later step (sections, clearance, display) would cost without bound.
inline constexpr std::size_t kMaxCadFaces = 200'000;

// Errors: FileNotFound, FileUnreadable, Parse (empty, not STEP/IGES, malformed), Geometry (no
// face in the file, e.g. curves only, or more than `maxFaces` faces), InvalidArgument
// (placement not a rotation).
Result<CadShape> readCadFile(const std::filesystem::path& path, const Placement& placement = {},
                             std::size_t maxFaces = kMaxCadFaces);

} // namespace bladeaxis::cad
