// html: index.html, the whole report on one self-contained page (results/html/html_report.hpp),
// rebuilt by every report from its tables and whatever figures/*.svg hold; `--open` shows it.
#include "results/html/html_report.hpp"
#include "results/reporters/reporter.hpp"

namespace mhb {

namespace {

class HtmlPage final : public Reporter {
public:
    std::string_view name() const override { return "html"; }
    std::string_view description() const override {
        return "index.html: every table and figure on one self-contained page";
    }
    ReporterKind kind() const override { return ReporterKind::every_report; }

    std::optional<std::filesystem::path> write_study(const StudyReportContext& study) const override {
        HtmlReportContent content{
            study.study.directory.string(), study.study.context_text, study.study.study_text, {}};
        for (const BudgetSection& budget : study.budgets)
            content.budgets.push_back({budget.budget, budget.folder, budget.directory, budget.tables,
                                       budget.figures_note, budget.figures_current});
        const std::filesystem::path page = write_html_report(study.directory, content);
        study.console << "HTML report (one self-contained page): " << page.string() << "\n  "
                      << file_url(page) << '\n';
        return page;
    }
};

} // namespace

std::unique_ptr<Reporter> html_page_reporter() {
    return std::make_unique<HtmlPage>();
}

} // namespace mhb
