#pragma once
// A self-contained HTML report page (inline CSS and SVG figures, no scripts, no external files),
// so a report written by `--batch` on a headless node opens anywhere and can be archived as is.

#include "core/report/svg_plot.h"

#include <string>
#include <vector>

namespace bladeaxis::report {

class HtmlPage {
  public:
    explicit HtmlPage(std::string title);

    void heading(const std::string& text, int level = 2);
    void paragraph(const std::string& text);
    // Cells are text (escaped); numeric-looking cells are right-aligned.
    void table(const std::vector<std::string>& header,
               const std::vector<std::vector<std::string>>& rows);
    void figure(const Plot& plot, const std::string& caption = {});

    std::string str() const;

  private:
    std::string m_title;
    std::string m_body;
};

} // namespace bladeaxis::report
