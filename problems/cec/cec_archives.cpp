// The two data archives and the SHA-256 list of their original files, embedded in the executable by the
// assembler's .incbin, so that the program needs no data directory at run time and nothing is read from disk
// or fetched. The paths come from problems/CMakeLists.txt, with MHB_CEC_ARCHIVES_HASH (the archives' SHA-256)
// on this file's compile line only so that a compiler cache sees a changed archive as a changed input.
#include "problems/cec/cec_archives.hpp"

#if !defined(MHB_CEC2017_ARCHIVE) || !defined(MHB_CEC2022_ARCHIVE) || !defined(MHB_CEC_SHA256SUMS) ||        \
    !defined(MHB_CEC_ARCHIVES_HASH)
#error                                                                                                       \
    "problems/CMakeLists.txt defines the paths MHB_CEC2017_ARCHIVE, MHB_CEC2022_ARCHIVE, MHB_CEC_SHA256SUMS and MHB_CEC_ARCHIVES_HASH"
#endif

// Hidden symbols (no GOT entry, nothing exported) in read-only data.
asm(".pushsection .rodata.mhb_cec_archives,\"a\",@progbits\n"
    ".balign 16\n"
    ".globl mhb_cec2017_archive_begin\n.hidden mhb_cec2017_archive_begin\n"
    "mhb_cec2017_archive_begin:\n"
    ".incbin \"" MHB_CEC2017_ARCHIVE "\"\n"
    ".globl mhb_cec2017_archive_end\n.hidden mhb_cec2017_archive_end\n"
    "mhb_cec2017_archive_end:\n"
    ".balign 16\n"
    ".globl mhb_cec2022_archive_begin\n.hidden mhb_cec2022_archive_begin\n"
    "mhb_cec2022_archive_begin:\n"
    ".incbin \"" MHB_CEC2022_ARCHIVE "\"\n"
    ".globl mhb_cec2022_archive_end\n.hidden mhb_cec2022_archive_end\n"
    "mhb_cec2022_archive_end:\n"
    ".globl mhb_cec_sha256sums_begin\n.hidden mhb_cec_sha256sums_begin\n"
    "mhb_cec_sha256sums_begin:\n"
    ".incbin \"" MHB_CEC_SHA256SUMS "\"\n"
    ".globl mhb_cec_sha256sums_end\n.hidden mhb_cec_sha256sums_end\n"
    "mhb_cec_sha256sums_end:\n"
    ".popsection\n");

#define MHB_HIDDEN __attribute__((visibility("hidden")))
extern "C" {
MHB_HIDDEN extern const unsigned char mhb_cec2017_archive_begin[];
MHB_HIDDEN extern const unsigned char mhb_cec2017_archive_end[];
MHB_HIDDEN extern const unsigned char mhb_cec2022_archive_begin[];
MHB_HIDDEN extern const unsigned char mhb_cec2022_archive_end[];
MHB_HIDDEN extern const char mhb_cec_sha256sums_begin[];
MHB_HIDDEN extern const char mhb_cec_sha256sums_end[];
}

namespace mhb::cec {

std::string_view embedded_archive_hash() {
    return MHB_CEC_ARCHIVES_HASH;
}

std::string_view embedded_sha256sums() {
    return {mhb_cec_sha256sums_begin,
            static_cast<std::size_t>(mhb_cec_sha256sums_end - mhb_cec_sha256sums_begin)};
}

std::span<const unsigned char> embedded_archive(Suite suite) {
    const unsigned char* begin =
        suite == Suite::cec2017 ? mhb_cec2017_archive_begin : mhb_cec2022_archive_begin;
    const unsigned char* end = suite == Suite::cec2017 ? mhb_cec2017_archive_end : mhb_cec2022_archive_end;
    return {begin, static_cast<std::size_t>(end - begin)};
}

} // namespace mhb::cec
