// html: index.html, the verdict first, then the key figures, the tables and the other figures, or
// a page per budget (results/html/html_report.hpp), rebuilt by every report from its tables and
// whatever figures/*.png hold; `--open` shows it.
#include "results/html/html_report.hpp"
#include "results/reporters/reporter.hpp"

namespace mhb {

namespace {

class HtmlPages final : public Reporter {
public:
    std::string_view name() const override { return "html"; }
    std::string_view description() const override {
        return "index.html: the verdict, key figures, every table and figure (a page per budget)";
    }
    ReporterKind kind() const override { return ReporterKind::every_report; }

    std::optional<std::filesystem::path> write_study(const StudyReportContext& study) const override {
        HtmlReportContent content{
            study.study.directory.string(), study.study.context_text, study.study.study_text, {}};
        for (const BudgetSection& budget : study.budgets)
            content.budgets.push_back({budget.budget, budget.folder, budget.directory, budget.tables,
                                       budget.verdict, budget.figures_note, budget.figures_current});
        const std::filesystem::path page = write_html_report(study.directory, content);
        study.console << "HTML report (verdict first): " << page.string() << "\n  " << file_url(page) << '\n';
        return page;
    }
};

} // namespace

std::unique_ptr<Reporter> html_page_reporter() {
    return std::make_unique<HtmlPages>();
}

} // namespace mhb
