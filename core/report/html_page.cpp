#include "core/report/html_page.h"

#include "core/base/number_io.h"
#include "core/report/markup.h"

#include <algorithm>

namespace bladeaxis::report {

namespace {

constexpr const char* kStyle = R"css(
body { font-family: "DejaVu Sans", Arial, sans-serif; margin: 24px; color: #222; max-width: 1100px; }
h1 { font-size: 22px; } h2 { font-size: 18px; margin-top: 28px; } h3 { font-size: 15px; }
table { border-collapse: collapse; margin: 8px 0 16px; font-size: 13px; }
th, td { border: 1px solid #ccc; padding: 3px 8px; }
th { background: #f0f0f0; } td.num { text-align: right; font-variant-numeric: tabular-nums; }
figure { margin: 12px 0 20px; } figcaption { font-size: 12px; color: #555; }
)css";

bool looksNumeric(const std::string& cell) {
    return !cell.empty() && parseNumber(cell.substr(0, cell.find_first_of(" %x"))).has_value();
}

} // namespace

HtmlPage::HtmlPage(std::string title) : m_title(std::move(title)) {}

void HtmlPage::heading(const std::string& text, int level) {
    const std::string tag = "h" + std::to_string(std::clamp(level, 1, 4));
    m_body += "<" + tag + ">" + escapeMarkup(text) + "</" + tag + ">\n";
}

void HtmlPage::paragraph(const std::string& text) {
    m_body += "<p>" + escapeMarkup(text) + "</p>\n";
}

void HtmlPage::table(const std::vector<std::string>& header,
                     const std::vector<std::vector<std::string>>& rows) {
    m_body += "<table>\n<tr>";
    for (const std::string& cell : header) {
        m_body += "<th>" + escapeMarkup(cell) + "</th>";
    }
    m_body += "</tr>\n";
    for (const auto& row : rows) {
        m_body += "<tr>";
        for (const std::string& cell : row) {
            m_body +=
                (looksNumeric(cell) ? "<td class=\"num\">" : "<td>") + escapeMarkup(cell) + "</td>";
        }
        m_body += "</tr>\n";
    }
    m_body += "</table>\n";
}

void HtmlPage::figure(const Plot& plot, const std::string& caption) {
    m_body += "<figure>" + renderSvg(plot);
    if (!caption.empty()) {
        m_body += "<figcaption>" + escapeMarkup(caption) + "</figcaption>";
    }
    m_body += "</figure>\n";
}

std::string HtmlPage::str() const {
    return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" +
           escapeMarkup(m_title) + "</title>\n<style>" + kStyle +
           "</style>\n</head>\n<body>\n<h1>" + escapeMarkup(m_title) + "</h1>\n" + m_body +
           "</body>\n</html>\n";
}

} // namespace bladeaxis::report
