#pragma once
// Module-internal: the OCCT side of CadShape, and the boundary that turns OCCT exceptions into
// Result errors. Only the module's own translation units include this header.

#include "core/base/error.h"
#include "core/cad/cad_shape.h"

#include <Standard_Failure.hxx>
#include <TopoDS_Shape.hxx>
#include <exception>
#include <mutex>
#include <string>

namespace bladeaxis::cad {

struct CadShape::Impl {
    TopoDS_Shape shape;
};

inline CadShape wrapShape(const TopoDS_Shape& shape) {
    return CadShape(std::make_shared<const CadShape::Impl>(CadShape::Impl{shape}));
}

inline const TopoDS_Shape& occtShape(const CadShape& shape) {
    return shape.impl().shape;
}

// OCCT's data-exchange settings (units, modes) live in a process-wide table (Interface_Static)
// that its readers and writers consult while they run, so every STEP/IGES transfer is serialised.
// The first use registers the STEP and IGES controllers and turns OpenCASCADE's console chatter
// (transfer statistics) down to failures: the module reports through Result values.
std::mutex& dataExchangeMutex();

// Runs `body` (returning a Result) and converts any exception escaping from OCCT into an error
// with `code`, prefixed by `what`: exceptions never leave the core.
template <class Body>
auto catchOcct(ErrorCode code, const std::string& what, Body&& body) -> decltype(body()) {
    try {
        return body();
    } catch (const Standard_Failure& failure) {
        const char* text = failure.GetMessageString();
        return makeError(code, what + ": OpenCASCADE failed (" + failure.DynamicType()->Name() +
                                   (text != nullptr && *text != '\0' ? std::string(": ") + text
                                                                     : std::string()) +
                                   ")");
    } catch (const std::exception& failure) {
        return makeError(code, what + ": " + failure.what());
    } catch (...) {
        return makeError(code, what + ": unknown failure in OpenCASCADE");
    }
}

} // namespace bladeaxis::cad
