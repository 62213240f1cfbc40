// The `bladeaxis` Python module (docs/python.md): the plug-in facade core/api for scripts and CAM
// post-processing hooks. It adds nothing to the engine: a job is a job file's JSON (a dict) or a
// job file's path, errors are the facade's errors raised as bladeaxis.BladeAxisError, and the
// outcome is the facade's JobOutcome with numpy arrays for the S-theta curves.
//
// Threads: the job runs with the GIL released so other Python threads keep going; the progress
// and warning callbacks re-acquire it. A Python exception in a callback (KeyboardInterrupt from
// Ctrl+C included, polled there) cancels the job and is re-raised by run_job once it returns:
// the engine reports errors as values and is not written to be unwound through.

#include "core/api/bladeaxis.h"
#include "core/base/error.h"
#include "core/base/progress.h"

#include <exception>
#include <filesystem>
#include <optional>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace py = pybind11;
namespace api = bladeaxis::api;

using bladeaxis::Error;
using bladeaxis::ErrorCode;

namespace {

constexpr const char* kJobSchema = "bladeaxis-job/1";

// bladeaxis.BladeAxisError, created when the module is imported. Deliberately never released:
// the module lives until the interpreter exits, and a static py::object would be destroyed
// after the interpreter is gone.
PyObject* g_errorType = nullptr;

// --- text and paths ------------------------------------------------------------------------

// The engine's text as str. NC programs and file names are bytes that need not be UTF-8 (a
// Latin-1 comment from an old post), so undecodable bytes become surrogate escapes instead of
// failing: text.encode("utf-8", "surrogateescape") gives back the exact bytes.
py::str toStr(std::string_view text) {
    PyObject* decoded =
        PyUnicode_DecodeUTF8(text.data(), static_cast<Py_ssize_t>(text.size()), "surrogateescape");
    if (decoded == nullptr) {
        throw py::error_already_set();
    }
    return py::reinterpret_steal<py::str>(decoded);
}

py::list toStrList(const std::vector<std::string>& texts) {
    py::list list;
    for (const std::string& text : texts) {
        list.append(toStr(text));
    }
    return list;
}

bool isPathLike(const py::handle& value) {
    const py::module_ os = py::module_::import("os");
    return py::isinstance<py::str>(value) || py::isinstance<py::bytes>(value) ||
           py::isinstance(value, os.attr("PathLike"));
}

// str, bytes or os.PathLike, encoded the way the operating system gets file names from Python,
// so any name Python can open reaches the engine unchanged.
std::filesystem::path toPath(const py::handle& value) {
    const py::bytes encoded = py::module_::import("os").attr("fsencode")(value);
    return std::filesystem::path(static_cast<std::string>(encoded));
}

// --- errors --------------------------------------------------------------------------------

// 0 is the engine's "unknown" line or column; Python says that with None.
py::object positiveOrNone(int value) {
    return value > 0 ? py::object(py::int_(value)) : py::object(py::none());
}

[[noreturn]] void raiseError(const Error& error) {
    const py::handle type(g_errorType);
    py::object exception = type(toStr(error.toString()));
    exception.attr("exit_code") = api::exitCodeFor(error);
    exception.attr("code") = bladeaxis::codeName(error.code);
    exception.attr("file") =
        error.where.file.empty() ? py::object(py::none()) : py::object(toStr(error.where.file));
    exception.attr("line") = positiveOrNone(error.where.line);
    exception.attr("column") = positiveOrNone(error.where.column);
    PyErr_SetObject(type.ptr(), exception.ptr());
    throw py::error_already_set();
}

template <class T>
T valueOrRaise(bladeaxis::Result<T> result) {
    if (!result) {
        raiseError(result.error());
    }
    return std::move(*result);
}

void raiseIfFailed(const bladeaxis::Status& status) {
    if (!status) {
        raiseError(status.error());
    }
}

// The exception class, with class-level None defaults so that a BladeAxisError a script raises
// itself (a hook refusing a program) has the same attributes.
PyObject* createErrorType() {
    py::dict defaults;
    for (const char* name : {"exit_code", "code", "file", "line", "column"}) {
        defaults[name] = py::none();
    }
    PyObject* type = PyErr_NewExceptionWithDoc(
        "bladeaxis.BladeAxisError",
        "A job BladeAxis refused or could not finish.\n\n"
        "str(error) is the message `bladeaxis --batch` prints, with file:line:column in front\n"
        "where there is a place to name.\n\n"
        "Attributes:\n"
        "    exit_code: the exit code `bladeaxis --batch` gives for it: 2 bad parameter,\n"
        "        3 input program, 4 machine file, 5 geometry or failed output check,\n"
        "        6 write failed, 7 cancelled, 1 internal error.\n"
        "    code: the kind, e.g. 'Parse', 'FileNotFound', 'InvalidArgument'.\n"
        "    file, line, column: where in an input the problem is; None when unknown.",
        PyExc_Exception, defaults.ptr());
    if (type == nullptr) {
        throw py::error_already_set();
    }
    return type;
}

// --- callbacks -----------------------------------------------------------------------------

// The job's progress and warning callbacks, run on the job's thread with the GIL re-acquired.
// The first Python exception (from a callable, or KeyboardInterrupt from a pending Ctrl+C) is
// kept and cancels the job; the engine's callbacks cannot throw through it.
class PythonCallbacks {
  public:
    PythonCallbacks(py::object progress, py::object warning)
        : m_progress(std::move(progress)), m_warning(std::move(warning)) {}
    PythonCallbacks(const PythonCallbacks&) = delete;
    PythonCallbacks& operator=(const PythonCallbacks&) = delete;

    // The facade's view; the progress callback is always installed because it is where Ctrl+C
    // is noticed, with or without a Python progress callable.
    api::Callbacks callbacks() {
        return api::Callbacks{
            [this](double fraction, std::string_view stage) { onProgress(fraction, stage); },
            [this](std::string_view message) { onWarning(message); }, &m_cancel};
    }

    // Call with the GIL held, after the job returned.
    void rethrowFailure() const {
        if (m_failure) {
            throw *m_failure;
        }
    }

  private:
    void onProgress(double fraction, std::string_view stage) {
        guarded([&] {
            // Python runs signal handlers only on the main thread between bytecodes, and the
            // job occupies that thread: this is where a pending Ctrl+C gets its turn.
            if (PyErr_CheckSignals() != 0) {
                throw py::error_already_set();
            }
            if (!m_progress.is_none()) {
                m_progress(fraction, toStr(stage));
            }
        });
    }

    void onWarning(std::string_view message) {
        guarded([&] {
            if (!m_warning.is_none()) {
                m_warning(toStr(message));
            }
        });
    }

    template <class Call>
    void guarded(Call&& call) {
        const py::gil_scoped_acquire gil;
        if (m_failure) {
            return; // cancelled: the job is on its way out, the callables are not called again
        }
        try {
            call();
        } catch (py::error_already_set& error) {
            fail(std::move(error));
        } catch (const std::exception& error) {
            // A C++ error inside pybind11 (a failed conversion): raised as RuntimeError.
            PyErr_SetString(PyExc_RuntimeError, error.what());
            fail(py::error_already_set());
        }
    }

    void fail(py::error_already_set error) {
        m_failure.emplace(std::move(error));
        m_cancel.requestCancel();
    }

    py::object m_progress;
    py::object m_warning;
    bladeaxis::CancelToken m_cancel;
    std::optional<py::error_already_set> m_failure;
};

// --- the outcome ---------------------------------------------------------------------------

// One layer in the S-theta plane (bladeaxis.Layer), converted once: read-only float64 arrays.
struct Layer {
    py::array_t<double> s, thetaOriginal, thetaRescheduled, thetaMin, thetaMax;
    std::size_t firstRecord = 0, lastRecord = 0;
    double junctionAngleRad = 0.0;
    bool keptOriginal = false;
};

// Read-only, so that a script cannot change the outcome it shares with the next reader.
py::array_t<double> readOnlyArray(const std::vector<double>& values) {
    py::array_t<double> array(static_cast<py::ssize_t>(values.size()), values.data());
    array.attr("flags").attr("writeable") = false;
    return array;
}

Layer toLayer(const api::LayerCurve& curve) {
    return Layer{readOnlyArray(curve.s),
                 readOnlyArray(curve.thetaOriginal),
                 readOnlyArray(curve.thetaRescheduled),
                 readOnlyArray(curve.thetaMin),
                 readOnlyArray(curve.thetaMax),
                 curve.firstRecord,
                 curve.lastRecord,
                 curve.junctionAngleRad,
                 curve.keptOriginal};
}

std::string layerRepr(const Layer& layer) {
    return "<bladeaxis.Layer records " + std::to_string(layer.firstRecord) + "-" +
           std::to_string(layer.lastRecord) + ", " + std::to_string(layer.s.size()) + " samples" +
           (layer.keptOriginal ? ", kept original" : "") + ">";
}

// A finished job (bladeaxis.Outcome). The report and the layers are converted on first use and
// kept: scripts read them repeatedly, and converting copies every sample.
class Outcome {
  public:
    explicit Outcome(api::JobOutcome outcome) : m_outcome(std::move(outcome)) {}

    py::object report() {
        if (!m_report) {
            m_report = py::module_::import("json").attr("loads")(toStr(m_outcome.reportJson()));
        }
        return m_report;
    }

    py::str summary() const { return toStr(m_outcome.summary()); }
    py::list warnings() const { return toStrList(m_outcome.warnings()); }
    bool rescheduled() const { return m_outcome.rescheduled(); }

    // A new list each time, of the same Layer objects, so a caller's list edits stay its own.
    py::object layers() {
        if (!m_layers) {
            py::list layers;
            for (const api::LayerCurve& curve : m_outcome.layers()) {
                layers.append(py::cast(toLayer(curve)));
            }
            m_layers = layers;
        }
        return m_layers.attr("copy")();
    }

    py::str programText() const { return toStr(valueOrRaise(m_outcome.programText())); }

    // The program is read back and checked before it is written: not instant on a large program.
    void writeProgram(const py::object& path) const {
        const std::filesystem::path target = toPath(path);
        bladeaxis::Status status;
        {
            const py::gil_scoped_release release;
            status = m_outcome.writeProgram(target);
        }
        raiseIfFailed(status);
    }

    void writeOutputs() const {
        bladeaxis::Status status;
        {
            const py::gil_scoped_release release;
            status = m_outcome.writeOutputs();
        }
        raiseIfFailed(status);
    }

    std::string repr() const {
        return std::string("<bladeaxis.Outcome ") +
               (m_outcome.rescheduled() ? "rescheduled" : "analysed only") + ", " +
               std::to_string(m_outcome.warnings().size()) + " warnings>";
    }

  private:
    api::JobOutcome m_outcome;
    py::object m_report;
    py::object m_layers;
};

// --- run_job -------------------------------------------------------------------------------

// A path value of a dict job (bytes or os.PathLike) as the str a job file holds. JSON is UTF-8
// text: a name that is not UTF-8 cannot be given in a job and is refused naming its key (it went
// through as an escaped lone surrogate and came back as "invalid JSON in the job file", and a
// bytes path made json.dumps report a "Circular reference").
py::object pathText(const py::handle& key, const py::handle& value) {
    const py::module_ os = py::module_::import("os");
    const py::object text = os.attr("fsdecode")(value);
    try {
        text.attr("encode")("utf-8");
    } catch (const py::error_already_set&) {
        throw py::value_error("job[" + py::repr(key).cast<std::string>() + "]: the path " +
                              py::repr(os.attr("fsencode")(value)).cast<std::string>() +
                              " is not UTF-8, which a job (JSON) cannot hold; link to the file "
                              "under a UTF-8 name");
    }
    return text;
}

// A dict (any mapping) as a job file's JSON. Path values (pathlib, bytes) are written as
// strings; NaN and infinity are refused here rather than written as invalid JSON.
std::string jobJson(const py::handle& job) {
    py::dict spec; // a copy, so the caller's dict does not gain a "schema" key
    spec.attr("update")(job);
    if (!spec.contains("schema")) {
        spec["schema"] = kJobSchema;
    }
    const py::object pathLike = py::module_::import("os").attr("PathLike");
    for (const auto& [key, value] : py::dict(spec)) {
        if (py::isinstance<py::bytes>(value) || py::isinstance(value, pathLike)) {
            spec[key] = pathText(key, value);
        }
    }
    const py::object text =
        py::module_::import("json").attr("dumps")(spec, py::arg("allow_nan") = false);
    return text.cast<std::string>();
}

void checkCallable(const py::object& value, const char* name) {
    if (!value.is_none() && !PyCallable_Check(value.ptr())) {
        throw py::type_error(std::string(name) + " must be callable or None");
    }
}

api::JobOutcome runJob(const py::object& job, const py::object& baseDir, const py::object& progress,
                       const py::object& warning) {
    checkCallable(progress, "progress");
    checkCallable(warning, "warning");
    const bool isMapping =
        py::isinstance(job, py::module_::import("collections.abc").attr("Mapping"));
    if (!isMapping && !isPathLike(job)) {
        throw py::type_error("job must be a dict (the keys of a job file, docs/job-file.md) or "
                             "the path of a job file");
    }
    if (!isMapping && !baseDir.is_none()) {
        throw py::value_error("base_dir applies to a job given as a dict; the paths in a job "
                              "file are relative to the file");
    }
    // Everything that needs Python is prepared before the GIL is released.
    const std::string json = isMapping ? jobJson(job) : std::string();
    const std::filesystem::path path =
        isMapping ? toPath(baseDir.is_none() ? py::module_::import("os").attr("getcwd")() : baseDir)
                  : toPath(job);
    PythonCallbacks callbacks(progress, warning);
    std::optional<bladeaxis::Result<api::JobOutcome>> result;
    {
        const py::gil_scoped_release release;
        result = isMapping ? api::runJobJson(json, path, callbacks.callbacks())
                           : api::runJobFile(path, callbacks.callbacks());
    }
    // The script's own exception first: the job's Cancelled error is only its consequence.
    callbacks.rethrowFailure();
    return valueOrRaise(std::move(*result));
}

// --- docstrings ----------------------------------------------------------------------------

constexpr const char* kModuleDoc =
    "BladeAxis: re-schedules the rotary A axis of four-axis helical blade toolpaths.\n\n"
    "run_job() runs a job as `bladeaxis --batch --job` does (docs/job-file.md) and returns an\n"
    "Outcome: the report, the per-layer S-theta curves and the re-scheduled program. Errors\n"
    "raise BladeAxisError with the command line's exit code. See docs/python.md.";

constexpr const char* kRunJobDoc =
    "Runs a BladeAxis job and returns its Outcome.\n\n"
    "job: a dict with the keys of a job file (docs/job-file.md; 'schema' is added when\n"
    "    missing, pathlib paths are accepted as values), or the path (str or os.PathLike)\n"
    "    of a job file.\n"
    "base_dir: the folder relative paths in a dict resolve against (default: the current\n"
    "    directory); outputs a dict names must lie inside it. Not allowed with a job file,\n"
    "    whose paths are relative to the file.\n"
    "progress: progress(fraction, stage) with fraction in [0, 1] of the whole job and stage\n"
    "    a str such as 'reading the program'; called a few times, at each stage.\n"
    "warning: warning(message) for each warning about the input as it is found.\n\n"
    "The callbacks run on the calling thread with the GIL held; the job itself releases the\n"
    "GIL. An exception raised in a callback cancels the job and propagates from run_job, as\n"
    "does KeyboardInterrupt (Ctrl+C, noticed at the next stage).\n\n"
    "Raises BladeAxisError when the job is refused or fails, TypeError/ValueError for\n"
    "arguments of the wrong kind.";

void bindLayer(py::module_& module) {
    py::class_<Layer>(module, "Layer",
                      "One layer of the re-scheduled pass in the S-theta plane.\n\n"
                      "The arrays are read-only numpy float64 arrays of equal length, one value "
                      "per sample:\n"
                      "S in mm along the layer's cutter path, theta in rad relative to the "
                      "layer's junction angle.")
        .def_readonly("s", &Layer::s, "S along the layer's cutter path, mm (numpy float64).")
        .def_readonly("theta_original", &Layer::thetaOriginal,
                      "theta of the input program, rad (numpy float64).")
        .def_readonly("theta_rescheduled", &Layer::thetaRescheduled,
                      "theta of the re-scheduled program, rad: monotone and inside "
                      "[theta_min, theta_max] unless kept_original (numpy float64).")
        .def_readonly("theta_min", &Layer::thetaMin,
                      "lower edge of the feasible channel, rad (numpy float64).")
        .def_readonly("theta_max", &Layer::thetaMax,
                      "upper edge of the feasible channel, rad (numpy float64).")
        .def_readonly("first_record", &Layer::firstRecord,
                      "first record of the layer, 0-based within the cutting pass.")
        .def_readonly("last_record", &Layer::lastRecord,
                      "last record of the layer, 0-based within the cutting pass.")
        .def_readonly("junction_angle_rad", &Layer::junctionAngleRad,
                      "the layer's junction angle, rad: theta is measured from it.")
        .def_readonly("kept_original", &Layer::keptOriginal,
                      "True when no monotone schedule exists and the layer keeps its original "
                      "orientation.")
        .def("__repr__", &layerRepr);
}

void bindOutcome(py::module_& module) {
    py::class_<Outcome>(module, "Outcome",
                        "The result of run_job(): report, layers and the re-scheduled program.")
        .def_property_readonly("report", &Outcome::report,
                               "report.json as a dict (docs/report-format.md); converted once.")
        .def_property_readonly("summary", &Outcome::summary,
                               "The before/after summary `bladeaxis --batch` prints (str).")
        .def_property_readonly("warnings", &Outcome::warnings,
                               "The job's warnings, one sentence each (list of str).")
        .def_property_readonly("rescheduled", &Outcome::rescheduled,
                               "True when the program was re-scheduled, False when the job only "
                               "analysed it (analyse_only).")
        .def_property_readonly("layers", &Outcome::layers,
                               "The layers in feed order (list of Layer); empty when only "
                               "analysed.")
        .def_property_readonly("program_text", &Outcome::programText,
                               "The whole re-scheduled program (str). Raises BladeAxisError "
                               "(exit_code 2) when the job only analysed the program.")
        .def("write_program", &Outcome::writeProgram, py::arg("path"),
             "Writes the re-scheduled program to path (str or os.PathLike) after the same "
             "checks as `bladeaxis -o`; atomic, never over the input program. Raises "
             "BladeAxisError.")
        .def("write_outputs", &Outcome::writeOutputs,
             "Writes what the job names: output_program, output_cl and the report folder "
             "output_dir. Raises BladeAxisError.")
        .def("__repr__", &Outcome::repr);
}

} // namespace

PYBIND11_MODULE(bladeaxis, module) {
    module.doc() = kModuleDoc;
    module.attr("__version__") = std::string(api::version());
    g_errorType = createErrorType();
    module.attr("BladeAxisError") = py::handle(g_errorType);
    bindLayer(module);
    bindOutcome(module);
    module.def(
        "run_job",
        [](const py::object& job, const py::object& baseDir, const py::object& progress,
           const py::object& warning) { return Outcome(runJob(job, baseDir, progress, warning)); },
        py::arg("job"), py::arg("base_dir") = py::none(), py::arg("progress") = py::none(),
        py::arg("warning") = py::none(), kRunJobDoc);
}
