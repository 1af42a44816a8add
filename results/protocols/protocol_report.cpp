#include "results/protocols/protocol_report.hpp"

#include <algorithm>

namespace mhb {

std::vector<Table> protocol_tables(const std::vector<const SuiteProtocol*>& protocols,
                                   ProtocolTablesPlace place, const StudyIndex& index,
                                   const std::string& reference, double alpha) {
    std::vector<Table> out;
    for (const SuiteProtocol* protocol : protocols)
        if (protocol->tables_place() == place)
            for (auto& t : protocol->tables(index, reference, alpha))
                out.push_back(std::move(t));
    return out;
}

bool writes_protocol_files(const std::vector<const SuiteProtocol*>& protocols) {
    return std::any_of(protocols.begin(), protocols.end(),
                       [](const SuiteProtocol* p) { return !p->files_folder().empty(); });
}

void write_protocol_files(const std::vector<const SuiteProtocol*>& protocols, const StudyIndex& index,
                          const std::filesystem::path& dir, std::ostream& console) {
    const auto in_force_folder = [&](std::string_view folder) {
        return std::any_of(protocols.begin(), protocols.end(),
                           [&](const SuiteProtocol* p) { return p->files_folder() == folder; });
    };
    for (const SuiteProtocol* other : all_protocols())
        if (!other->files_folder().empty() && !in_force_folder(other->files_folder()))
            other->remove_files(dir);
    for (const SuiteProtocol* protocol : protocols)
        if (!protocol->files_folder().empty())
            protocol->write_files(index, dir, console);
}

} // namespace mhb
