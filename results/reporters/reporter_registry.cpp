#include "results/reporters/reporter_registry.hpp"

#include <algorithm>
#include <stdexcept>

#include "results/table_model/table.hpp"

namespace mhb {

// The built-in reporters, each defined in its own file: a declaration here and an entry in
// builtin_reporters(), whose order is the order a report calls them.
std::unique_ptr<Reporter> markdown_tables_reporter();
std::unique_ptr<Reporter> latex_tables_reporter();
std::unique_ptr<Reporter> csv_tables_reporter();
std::unique_ptr<Reporter> console_tables_reporter();
std::unique_ptr<Reporter> protocol_files_reporter();
std::unique_ptr<Reporter> ioh_export_reporter();
std::unique_ptr<Reporter> html_page_reporter();

namespace {

std::vector<std::shared_ptr<const Reporter>> builtin_reporters() {
    std::vector<std::shared_ptr<const Reporter>> all;
    for (auto make :
         {markdown_tables_reporter, latex_tables_reporter, csv_tables_reporter, console_tables_reporter,
          protocol_files_reporter, ioh_export_reporter, html_page_reporter})
        all.push_back(make());
    return all;
}

std::vector<std::shared_ptr<const Reporter>>& registered() {
    static std::vector<std::shared_ptr<const Reporter>> all = builtin_reporters();
    return all;
}

const TableFormatReporter* as_table_format(const Reporter& reporter) {
    return reporter.kind() == ReporterKind::table_format ? dynamic_cast<const TableFormatReporter*>(&reporter)
                                                         : nullptr;
}

} // namespace

const std::vector<std::shared_ptr<const Reporter>>& reporters() {
    return registered();
}

void register_reporter(std::shared_ptr<const Reporter> reporter) {
    if (reporter == nullptr)
        throw std::logic_error("register_reporter: no reporter");
    if (find_reporter(reporter->name()) != nullptr)
        throw std::logic_error("reporter '" + std::string(reporter->name()) + "' is registered twice");
    registered().push_back(std::move(reporter));
}

void unregister_reporter(std::string_view name) {
    std::erase_if(registered(), [&](const auto& reporter) { return reporter->name() == name; });
}

const Reporter* find_reporter(std::string_view name) {
    for (const auto& reporter : registered())
        if (reporter->name() == name)
            return reporter.get();
    return nullptr;
}

std::vector<std::string> table_format_names() {
    std::vector<std::string> names;
    for (const auto& reporter : registered())
        if (as_table_format(*reporter) != nullptr)
            names.emplace_back(reporter->name());
    return names;
}

std::set<std::string> default_table_formats() {
    std::set<std::string> names;
    for (const auto& reporter : registered())
        if (const TableFormatReporter* format = as_table_format(*reporter);
            format && format->selected_by_default())
            names.emplace(reporter->name());
    return names;
}

std::optional<std::string> table_format_error(const std::set<std::string>& formats) {
    const std::string known = join(table_format_names(), ", ");
    if (formats.empty())
        return "--format: choose at least one of " + known;
    for (const auto& f : formats) {
        const Reporter* reporter = find_reporter(f);
        if (reporter == nullptr || reporter->kind() != ReporterKind::table_format)
            return "--format: '" + (f.size() > 40 ? f.substr(0, 37) + "..." : f) + "' is not one of " + known;
    }
    return std::nullopt;
}

std::vector<const Reporter*> selected_reporters(const std::set<std::string>& formats) {
    std::vector<const Reporter*> selected;
    for (const auto& reporter : registered())
        if (reporter->kind() == ReporterKind::every_report ||
            formats.count(std::string(reporter->name())) != 0)
            selected.push_back(reporter.get());
    return selected;
}

} // namespace mhb
