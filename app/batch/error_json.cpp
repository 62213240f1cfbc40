#include "app/batch/error_json.h"

#include <nlohmann/json.hpp>

namespace bladeaxis::app {

namespace {

using Json = nlohmann::json;

// A place not known (0, "") is null, never 0 or "": a script tests for it, not for a number.
Json placeOf(const Error& error) {
    const SourceLocation& where = error.where;
    return {{"file", where.file.empty() ? Json(nullptr) : Json(where.file)},
            {"line", where.line > 0 ? Json(where.line) : Json(nullptr)},
            {"column", where.column > 0 ? Json(where.column) : Json(nullptr)},
            {"message", error.message}};
}

} // namespace

std::string errorJsonText(const Error& error, int exitCode) {
    Json object = placeOf(error);
    object["code"] = codeName(error.code);
    object["exit_code"] = exitCode;
    Json more = Json::array();
    for (const Error& further : error.more) {
        more.push_back(placeOf(further));
    }
    object["more"] = std::move(more);
    return Json{{"error", std::move(object)}}.dump(2) + '\n';
}

} // namespace bladeaxis::app
