#pragma once
// An APT / ISO 4343 CLDATA / Siemens NX CLSF program as read: the toolpath plus what the
// rewriter needs to change only the GOTO numbers and keep every other byte.

#include "core/toolpath/toolpath.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace bladeaxis::io::cl {

// Where the GOTO of one record sits in the source text, and the modal state it was read in.
// Kept small: the rewriter re-scans the statement from `textBegin` to find the numbers.
// The statement a record comes from.
enum class AptMotion : std::uint8_t {
    Goto,  // GOTO/x,y,z[,i,j,k]
    From,  // FROM/x,y,z[,i,j,k]: the start position
    Delta, // GODLTA/dx,dy,dz (3 numbers) or GODLTA/d (1 number, along the tool axis)
};

// A local coordinate system set by MSYS/x,y,z,xi,xj,xk,yi,yj,yk: GOTO numbers after it are in
// this frame, world = origin + rotation * local (rotation columns: the local X, Y, Z axes).
struct AptFrame {
    Vec3 origin = Vec3::Zero(); // mm
    Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();

    Vec3 pointToWorld(const Vec3& local) const { return origin + rotation * local; }
    Vec3 pointToLocal(const Vec3& world) const { return rotation.transpose() * (world - origin); }
};

struct AptRecordSource {
    std::size_t textBegin = 0;     // start of the statement's first line in AptProgram::text
    std::uint32_t multaxEpoch = 0; // number of MULTAX statements before this GOTO
    std::uint8_t numberCount = 3;  // 3 (x,y,z) or 6 (x,y,z,i,j,k)
    bool multaxOn = false;         // MULTAX was on when this GOTO was read
    bool inches = false;           // UNITS/INCHES was in force (numbers are inches)
    AptMotion motion = AptMotion::Goto;
    std::uint32_t frame = 0; // index into AptProgram::frames
};

struct AptProgram {
    toolpath::Toolpath path;                  // format Apt; one record per GOTO
    std::string text;                         // the original file, byte for byte
    std::vector<AptRecordSource> source;      // parallel to path.records
    std::vector<AptFrame> frames{AptFrame{}}; // frame 0 is the base frame (no MSYS)
    bool crlf = false;                        // the first line ends with CR LF
};

} // namespace bladeaxis::io::cl
