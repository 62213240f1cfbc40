#include "core/cad/cad_files.h"

#include "core/base/file_io.h"
#include "core/cad/detail/occt_shape.h"

#include <BRepBuilderAPI_Transform.hxx>
#include <BinTools.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESControl_Controller.hxx>
#include <IGESControl_Reader.hxx>
#include <IGESControl_Writer.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_Printer.hxx>
#include <STEPControl_Controller.hxx>
#include <STEPControl_Reader.hxx>
#include <STEPControl_Writer.hxx>
#include <TopExp_Explorer.hxx>
#include <XSControl_Reader.hxx>
#include <algorithm>
#include <atomic>
#include <cctype>
#include <chrono>
#include <csignal>
#include <fstream>
#include <gp_Trsf.hxx>
#include <string>
#include <sys/wait.h>
#include <system_error>
#include <thread>
#include <unistd.h>

namespace bladeaxis::cad {
namespace fs = std::filesystem;

std::mutex& dataExchangeMutex() {
    static std::mutex mutex;
    static const bool ready = [] {
        // The data-exchange parameters exist only once the controllers are registered: setting
        // a unit before that would be silently ignored.
        STEPControl_Controller::Init();
        IGESControl_Controller::Init();
        // OpenCASCADE reports through its messenger, to standard output: our errors carry what
        // the user needs, and standard output belongs to the batch report (--json).
        Message::DefaultMessenger()->ChangePrinters().Clear();
        return true;
    }();
    (void)ready;
    return mutex;
}
namespace {

const char* kExpected = "expected a STEP or IGES model of the blade surface";

const char* stepUnitName(LengthUnit unit) {
    switch (unit) {
    case LengthUnit::Inch:
        return "INCH";
    case LengthUnit::Metre:
        return "M";
    case LengthUnit::Millimetre:
        break;
    }
    return "MM";
}

int countSubShapes(const TopoDS_Shape& shape, TopAbs_ShapeEnum kind) {
    int count = 0;
    for (TopExp_Explorer it(shape, kind); it.More(); it.Next()) {
        ++count;
    }
    return count;
}

// OCCT writes to a file name; the file is produced beside the target and renamed into place so
// that a failed write never leaves a partial model behind.
Status writeWithOcct(const CadShape& shape, const fs::path& temporary, CadFormat format,
                     LengthUnit unit) {
    const std::lock_guard lock(dataExchangeMutex());
    const std::string name = temporary.string();
    if (!Interface_Static::SetCVal("xstep.cascade.unit", "MM")) {
        return makeError(ErrorCode::Internal, "OpenCASCADE data exchange is not initialised");
    }
    if (format == CadFormat::Step) {
        if (!Interface_Static::SetCVal("write.step.unit", stepUnitName(unit)) ||
            !Interface_Static::SetCVal("write.step.schema", "AP214IS")) {
            return makeError(ErrorCode::Internal, "OpenCASCADE refused the STEP unit or schema");
        }
        STEPControl_Writer writer;
        if (writer.Transfer(occtShape(shape), STEPControl_AsIs) != IFSelect_RetDone ||
            writer.Write(name.c_str()) != IFSelect_RetDone) {
            return makeError(ErrorCode::WriteFailed, "OpenCASCADE could not write the STEP model");
        }
        return {};
    }
    // Mode 0 writes trimmed surfaces (entity 144), which every IGES reader understands.
    IGESControl_Writer writer(stepUnitName(unit), 0);
    if (!writer.AddShape(occtShape(shape))) {
        return makeError(ErrorCode::WriteFailed, "OpenCASCADE could not convert the shape to IGES");
    }
    writer.ComputeModel();
    if (!writer.Write(name.c_str())) {
        return makeError(ErrorCode::WriteFailed, "OpenCASCADE could not write the IGES model");
    }
    return {};
}

std::string readHead(const fs::path& path, std::size_t bytes) {
    std::ifstream in(path, std::ios::binary);
    std::string head(bytes, '\0');
    in.read(head.data(), static_cast<std::streamsize>(bytes));
    head.resize(static_cast<std::size_t>(std::max<std::streamsize>(0, in.gcount())));
    return head;
}

std::string lowerExtension(const fs::path& path) {
    std::string ext = path.extension().string();
    std::ranges::transform(ext, ext.begin(),
                           [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

// IGES fixed format: 80-column records with the section letter (S start, G global) in column 73.
bool looksLikeIges(const std::string& head) {
    const std::size_t end = head.find_first_of("\r\n");
    const std::string first = head.substr(0, end);
    return first.size() >= 73 && (first[72] == 'S' || first[72] == 'G');
}

Status checkPlacement(const Placement& placement) {
    const Mat3& r = placement.rotation;
    const bool finite = r.allFinite() && placement.translation.allFinite();
    if (!finite || !(r.transpose() * r).isApprox(Mat3::Identity(), 1e-9) ||
        std::abs(r.determinant() - 1.0) > 1e-9) {
        return makeError(ErrorCode::InvalidArgument,
                         "blade placement: the rotation must be orthonormal with determinant +1 "
                         "and the translation finite");
    }
    return {};
}

// The caller holds dataExchangeMutex() (in the parent: a forked child inherits it locked).
Result<TopoDS_Shape> transferModel(const fs::path& path, CadFormat format) {
    // Coordinates come out in mm whatever unit the file declares.
    if (!Interface_Static::SetCVal("xstep.cascade.unit", "MM")) {
        return makeError(ErrorCode::Internal, "OpenCASCADE data exchange is not initialised");
    }
    STEPControl_Reader stepReader;
    IGESControl_Reader igesReader;
    XSControl_Reader& reader = format == CadFormat::Step
                                   ? static_cast<XSControl_Reader&>(stepReader)
                                   : static_cast<XSControl_Reader&>(igesReader);
    const char* kind = format == CadFormat::Step ? "STEP" : "IGES";
    const SourceLocation where{path.string(), 0, 0};
    const std::string name = path.string();
    if (reader.ReadFile(name.c_str()) != IFSelect_RetDone) {
        return makeError(ErrorCode::Parse,
                         std::string("malformed ") + kind + " file (" + kExpected + ")", where);
    }
    if (reader.TransferRoots() == 0 || reader.NbShapes() == 0) {
        return makeError(ErrorCode::Geometry,
                         std::string("the ") + kind +
                             " file holds no transferable geometry (expected faces, shells or "
                             "solids)",
                         where);
    }
    return reader.OneShape();
}

// Exit codes of the reading child process.
// Distinct from 1, which runtimes such as a sanitizer use when they end a process.
enum ChildExit : int {
    kShapeWritten = 0,
    kMalformed = 65,
    kNoGeometry = 66,
    kFailed = 67,
    kTooManyFaces = 68, // the handover file holds the face count as text
};

constexpr std::chrono::seconds kReadTimeout{300};

Error childError(const fs::path& path, CadFormat format, const std::string& what) {
    const char* kind = format == CadFormat::Step ? "STEP" : "IGES";
    return Error{ErrorCode::Parse,
                 std::string("malformed ") + kind + " file: " + what + " (" + kExpected + ")",
                 {path.string(), 0, 0},
                 {}};
}

// OpenCASCADE 7.6's STEP translator dereferences missing entities of a malformed file (a
// segmentation fault, not an exception: found by mutating a valid file). Untrusted files are
// therefore translated in a forked child process, which hands the shape back as an OCCT binary
// BRep file; a crash, an exception or a hang of the child becomes an error of this file.
Error tooManyFaces(const fs::path& path, const fs::path& handover, std::size_t maxFaces) {
    std::string count = "more than " + std::to_string(maxFaces);
    if (std::ifstream in(handover); in) {
        std::getline(in, count);
    }
    return Error{ErrorCode::Geometry,
                 "the model has " + count + " faces, expected at most " + std::to_string(maxFaces) +
                     " (a blade model has tens to thousands): export the blade alone, not the "
                     "assembly, the fixture or a meshed scan",
                 {path.string(), 0, 0},
                 {}};
}

Result<TopoDS_Shape> transferInChild(const fs::path& path, CadFormat format, std::size_t maxFaces) {
    static std::atomic<unsigned> counter{0};
    const fs::path handover =
        fs::temp_directory_path() /
        ("bladeaxis_cad_" + std::to_string(::getpid()) + "_" + std::to_string(counter++) + ".brep");
    const std::lock_guard lock(dataExchangeMutex());
    const pid_t child = ::fork();
    if (child < 0) {
        return makeError(ErrorCode::Internal, "cannot start the CAD reader process",
                         {path.string(), 0, 0});
    }
    if (child == 0) {
        int code = kFailed;
        try {
            const Result<TopoDS_Shape> shape = transferModel(path, format);
            const auto faces =
                shape ? static_cast<std::size_t>(countSubShapes(*shape, TopAbs_FACE)) : 0;
            if (!shape) {
                code = shape.error().code == ErrorCode::Parse ? kMalformed : kNoGeometry;
            } else if (faces > maxFaces) {
                std::ofstream(handover) << faces << "\n";
                code = kTooManyFaces;
            } else if (BinTools::Write(*shape, handover.c_str())) {
                code = kShapeWritten;
            }
        } catch (...) {
            code = kFailed;
        }
        ::_exit(code); // no atexit handlers or static destructors of the parent's state
    }
    int status = 0;
    const auto deadline = std::chrono::steady_clock::now() + kReadTimeout;
    while (::waitpid(child, &status, WNOHANG) == 0) {
        if (std::chrono::steady_clock::now() > deadline) {
            ::kill(child, SIGKILL);
            ::waitpid(child, &status, 0);
            return std::unexpected(childError(path, format, "reading timed out"));
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    std::error_code ignored;
    if (WIFSIGNALED(status)) {
        fs::remove(handover, ignored);
        return std::unexpected(childError(path, format,
                                          "OpenCASCADE crashed on it (signal " +
                                              std::to_string(WTERMSIG(status)) + ")"));
    }
    const int code = WIFEXITED(status) ? WEXITSTATUS(status) : kFailed;
    if (code == kTooManyFaces) {
        Error error = tooManyFaces(path, handover, maxFaces);
        fs::remove(handover, ignored);
        return std::unexpected(std::move(error));
    }
    if (code != kShapeWritten && code != kMalformed && code != kNoGeometry && code != kFailed) {
        fs::remove(handover, ignored);
        return std::unexpected(childError(
            path, format, "the reader process ended with exit code " + std::to_string(code)));
    }
    if (code == kMalformed) {
        return std::unexpected(childError(path, format, "syntax errors"));
    }
    if (code == kNoGeometry) {
        return makeError(ErrorCode::Geometry,
                         std::string("the ") + (format == CadFormat::Step ? "STEP" : "IGES") +
                             " file holds no transferable geometry (expected faces, shells or "
                             "solids)",
                         {path.string(), 0, 0});
    }
    TopoDS_Shape shape;
    const bool read = code == kShapeWritten && BinTools::Read(shape, handover.c_str());
    fs::remove(handover, ignored);
    if (!read) {
        return std::unexpected(childError(path, format, "OpenCASCADE failed to translate it"));
    }
    return shape;
}

Result<CadShape> placeShape(const TopoDS_Shape& shape, const Placement& placement) {
    if (placement.rotation.isIdentity(0.0) && placement.translation.isZero(0.0)) {
        return wrapShape(shape);
    }
    const Mat3& r = placement.rotation;
    const Vec3& t = placement.translation;
    gp_Trsf transform;
    transform.SetValues(r(0, 0), r(0, 1), r(0, 2), t.x(), r(1, 0), r(1, 1), r(1, 2), t.y(), r(2, 0),
                        r(2, 1), r(2, 2), t.z());
    BRepBuilderAPI_Transform placed(shape, transform, /*copy=*/true);
    return wrapShape(placed.Shape());
}

} // namespace

Status writeCadFile(const CadShape& shape, const fs::path& path, CadFormat format,
                    LengthUnit unit) {
    const SourceLocation where{path.string(), 0, 0};
    if (shape.isNull() || shape.faceCount() == 0) {
        return makeError(ErrorCode::InvalidArgument, "nothing to write: the shape has no face",
                         where);
    }
    // A short name beside the target, so a target with the longest legal name can be written.
    const fs::path temporary =
        temporaryNameIn(path.has_parent_path() ? path.parent_path() : fs::path("."));
    Status written = catchOcct(ErrorCode::WriteFailed, path.string(),
                               [&] { return writeWithOcct(shape, temporary, format, unit); });
    std::error_code ec;
    if (written) {
        fs::rename(temporary, path, ec);
        if (!ec) {
            return {};
        }
    }
    fs::remove(temporary, ec);
    if (!written) {
        written.error().where = where;
        return written;
    }
    return makeError(ErrorCode::WriteFailed, "cannot move the written model into place", where);
}

Result<CadShape> placedShape(const CadShape& shape, const Placement& placement) {
    if (shape.isNull()) {
        return makeError(ErrorCode::InvalidArgument, "nothing to place: the shape is empty");
    }
    if (Status ok = checkPlacement(placement); !ok) {
        return std::unexpected(ok.error());
    }
    return catchOcct(ErrorCode::Geometry, "placing a shape",
                     [&]() -> Result<CadShape> { return placeShape(occtShape(shape), placement); });
}

Placement toPlacement(const AxisRotationPlacement& placement) {
    const Vec3& angles = placement.rotationXyz;
    return {rotationZ(angles.z()) * rotationY(angles.y()) * rotationX(angles.x()),
            placement.translation};
}

Result<CadFormat> detectCadFormat(const fs::path& path) {
    const std::string head = readHead(path, 4096);
    const std::size_t start = head.find_first_not_of(" \t\r\n");
    if (start != std::string::npos && head.compare(start, 13, "ISO-10303-21;") == 0) {
        return CadFormat::Step;
    }
    if (looksLikeIges(head)) {
        return CadFormat::Iges;
    }
    const std::string ext = lowerExtension(path);
    if (ext == ".step" || ext == ".stp") {
        return CadFormat::Step;
    }
    if (ext == ".iges" || ext == ".igs") {
        return CadFormat::Iges;
    }
    return makeError(ErrorCode::Parse,
                     std::string("neither a STEP (ISO-10303-21) nor an IGES file (") + kExpected +
                         ")",
                     {path.string(), 0, 0});
}

Result<CadShape> readCadFile(const fs::path& path, const Placement& placement,
                             std::size_t maxFaces) {
    const SourceLocation where{path.string(), 0, 0};
    if (Status ok = checkPlacement(placement); !ok) {
        return std::unexpected(ok.error());
    }
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (!fs::exists(status)) {
        return makeError(ErrorCode::FileNotFound, std::string("no such file (") + kExpected + ")",
                         where);
    }
    if (!fs::is_regular_file(status) || !std::ifstream(path, std::ios::binary)) {
        return makeError(ErrorCode::FileUnreadable,
                         std::string("cannot open the file for reading (") + kExpected + ")",
                         where);
    }
    if (fs::file_size(path, ec) == 0 || ec) {
        return makeError(ErrorCode::Parse, std::string("empty file (") + kExpected + ")", where);
    }
    const Result<CadFormat> format = detectCadFormat(path);
    if (!format) {
        return std::unexpected(format.error());
    }
    return catchOcct(ErrorCode::Parse, path.string(), [&]() -> Result<CadShape> {
        const Result<TopoDS_Shape> shape = transferInChild(path, *format, maxFaces);
        if (!shape) {
            return std::unexpected(shape.error());
        }
        if (countSubShapes(*shape, TopAbs_FACE) == 0) {
            return makeError(ErrorCode::Geometry,
                             "the model has no face (found " +
                                 std::to_string(countSubShapes(*shape, TopAbs_EDGE)) +
                                 " edges and " +
                                 std::to_string(countSubShapes(*shape, TopAbs_VERTEX)) +
                                 " vertices; expected surfaces, shells or solids)",
                             where);
        }
        return placeShape(*shape, placement);
    });
}

} // namespace bladeaxis::cad
