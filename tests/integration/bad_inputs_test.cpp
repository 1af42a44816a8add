// The catalogue of bad inputs (issue 9): every subcommand and every surface a user can get wrong
// (options, specs, grids, study files, presets, dataset CSVs, points files, study directories,
// files the OS refuses), each with the exact command, its exit code (2: the command line is
// wrong, 1: the work failed) and what stderr must say. Each case runs the real `mhbench` in a
// scratch directory of its own, and the directory must be exactly as it was afterwards: nothing
// half-written, no runs.csv, no report, no .tmp file, and no output on stdout.
//
// Adding a case is one line in `catalogue()`. A few cases are accepted inputs (exit 0: a
// byte-order mark) kept here beside the inputs they resemble.
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "cli_harness.hpp"
#include "runner/distribution/distributed.hpp"

namespace {
namespace fs = std::filesystem;
using mhb::testing_cli::CliResult;
using mhb::testing_cli::lines_of;
using mhb::testing_cli::read_text;

// What stderr must hold.
struct Stderr {
    enum Kind { exact_lines, one_line_containing, containing } kind = exact_lines;
    std::vector<std::string> text;
};
Stderr stderr_says(std::vector<std::string> lines) {
    return {Stderr::exact_lines, std::move(lines)};
}
// One line holding `part` (for messages with an OS's wording or a path that varies).
Stderr one_line(std::string part) {
    return {Stderr::one_line_containing, {std::move(part)}};
}
// Any number of lines holding `part` (usage texts).
Stderr mentions(std::string part) {
    return {Stderr::containing, {std::move(part)}};
}

struct BadInputCase {
    std::string setup; // shell commands run first in the case's directory; $F is the fixtures folder
    std::string args;  // mhbench's arguments as typed in a shell there, or a whole command in (...)
    int exit_code;
    Stderr err;
    std::string may_write = ""; // a path the command may change (an accepted input's output)
};

// Text of n copies of c, made by the shell ($(...)); command-line arguments stay below the
// kernel's 128 KiB limit per argument, files get 1 MiB.
std::string repeated(char c, int n) {
    return "$(head -c " + std::to_string(n) + " /dev/zero | tr '\\0' '" + std::string(1, c) + "')";
}

const std::string big_digits = repeated('1', 100000);
const std::string excerpt_of_ones = "'1111111111111111111111111111111111111...' (100000 characters)";

// A valid dataset CSV with one line changed: $F/good.csv (the header on line 1, then 10 rows at
// id = 0 and 10 injected, no metadata) with `sed` applied.
std::string dataset_with(const std::string& sed) {
    return "sed '" + sed + "' $F/good.csv > d.csv";
}

const std::string tiny_run = " --problems sphere:dim=2 --runs 2 --evaluations 100 --no-report --out s";
const std::string study_copy = "cp -r $F/study s";
// The same as a study from before the marker held each rendered file's size and checksum, so
// that an edited file reaches the CSV reader's own checks.
const std::string old_study_copy = study_copy + " && sed -i '/ bytes, crc32c /d' s/.mhbench-study";
// The same having lost its marker (as `cp DIR/* NEW/` loses it): store.bin vouches for the rest.
const std::string unmarked_study_copy = study_copy + " && rm s/.mhbench-study";
const std::string unmarked_refusal =
    " (s has no .mhbench-study to vouch for it, so it was checked against store.bin); run the study's "
    "command again to render it from store.bin";
// Shards 1/2 and 2/2 of a small study, in directories 1 and 2.
const std::string two_shards = "M='" MHB_CLI_PATH "'; for i in 1 2; do $M run --algorithms random-search "
                               "--problems sphere:dim=2 --runs 2 --evaluations 100 --quiet --shard $i/2 "
                               "--out $i || exit 1; done";

// clang-format off
std::vector<BadInputCase> catalogue() {
    return {
        // ---- the top level
        {"", "", 2, mentions("Usage: mhbench <command> [options]")},
        {"", "bogus", 2, stderr_says({"mhbench: unknown command 'bogus'; run mhbench --help for the list"})},
        {"", "--bogus", 2, stderr_says({"mhbench: unknown command '--bogus'; run mhbench --help for the list"})},
        {"", "--version --bogus", 2, stderr_says({"mhbench: --version takes no other argument (got '--bogus')"})},

        // ---- run: options
        {"", "run --algorithms random-search" + tiny_run + " --bogus", 2,
         stderr_says({"mhbench run: unrecognised option '--bogus' (see mhbench run --help)"})},
        {"", "run --algorithms random-search --problems sphere --out s", 2,
         stderr_says({"mhbench run: budget: give a number of iterations or of evaluations (or both)"})},
        {"", "run --algorithms random-search --problems sphere --iterations 5 --runs 0 --out s", 2,
         stderr_says({"mhbench run: study: runs = 0 is outside [1, 1000000]"})},
        {"", "run --algorithms random-search --problems sphere --evaluations 1e300 --out s", 2,
         stderr_says({"mhbench run: evaluations = 1e300 is too large (at most 1000000000000000)"})},
        {"", "run --algorithms random-search --problems sphere --evaluations '10000*D' --out s", 2,
         stderr_says({"mhbench run: budget: parameter 'evaluations' = 10000*D multiplies by 'D', not by dim; write a "
               "count N, N*dim (N x the problem's dimension) or dimD:N+dimD:N+... (N at each dimension D "
               "listed), e.g. 10000*dim or dim10:200000+dim20:1000000"})},
        {"", "run --algorithms random-search --problems sphere:dim=2 --budget evaluations=dim10:100 --out s", 2,
         stderr_says({"mhbench run: budget 'evaluations=dim10:100' gives no evaluations at dimension 2 (problem "
               "'sphere:dim=2'); it lists 10"})},
        {"", "run --algorithms random-search" + tiny_run + " --protocol cec2017", 2,
         stderr_says({"mhbench run: protocol cec2017: problem 'sphere:dim=2' is not of the cec2017 suite; the protocol's "
               "tables and result files cover its functions only (write cec2017:f=...,dim=...)"})},
        {"", "run --algorithms random-search" + tiny_run + " --protocol cec2030", 2,
         stderr_says({"mhbench run: protocol = cec2030 is not one of {cec2017, cec2022, pmsm-paper, none}"})},
        {"", "run --algorithms random-search" + tiny_run + " --protocol pmsm-paper", 2,
         stderr_says({"mhbench run: protocol pmsm-paper: the study has no pmsm problem (the paper's tables are of "
                      "PMSM identification)"})},
        {"", "run --algorithms random-search --problems sphere --runs 1e300 --iterations 5 --out s", 2,
         stderr_says({"mhbench run: runs = 1e300 is too large (at most 1000000)"})},
        // mhbench plan: what it plans must be said, and in range.
        {"", "plan", 2,
         stderr_says({"mhbench plan: give --effect D (problems needed) or --precision E with --sd S or --pilot DIR "
                      "(runs per problem); see --help"})},
        {"", "plan --effect 0", 2, stderr_says({"mhbench plan: effect = 0 is outside (0, inf)"})},
        {"", "plan --effect 0.5 --power 1", 2, stderr_says({"mhbench plan: power = 1 is outside (0, 1)"})},
        {"", "plan --precision 0.1", 2, stderr_says({"mhbench plan: --precision needs --sd S or --pilot DIR (one of them)"})},
        {"", "plan --effect 0.5 --test anova", 2,
         stderr_says({"mhbench plan: --test = anova is not one of {wilcoxon, t}"})},
        // Runs by precision: the rule must be whole, and rounds cannot be split into shards.
        {"", "run --algorithms random-search --problems sphere --iterations 5 --runs auto --out s", 2,
         stderr_says({"mhbench run: runs = auto needs precision = the standard error to reach on log10(f - f*), "
                      "e.g. --precision 0.05"})},
        {"", "run --algorithms random-search --problems sphere --iterations 5 --precision 0.1 --out s", 2,
         stderr_says({"mhbench run: precision, max-runs, initial-runs and round-runs go with runs = auto"})},
        {"", "run --algorithms random-search --problems sphere --iterations 5 --runs auto --precision nan --out s", 2,
         stderr_says({"mhbench run: precision = nan is not a number in (0, inf)"})},
        {"", "run --algorithms random-search --problems sphere --iterations 5 --runs auto --precision 0.1 "
             "--max-runs 8 --initial-runs 10 --out s",
         2, stderr_says({"mhbench run: initial-runs = 10 is outside [2, max-runs = 8]"})},
        {"", "run --algorithms random-search --problems sphere --iterations 5 --runs auto --precision 0.1 "
             "--shard 1/2 --out s",
         2, stderr_says({"mhbench run: runs = auto decides each round from the results of the last, which a shard "
                         "cannot see; give a fixed --runs to shard the study (or run it under mpirun)"})},
        {"", "run --algorithms random-search --problems sphere --iterations lots --out s", 2,
         stderr_says({"mhbench run: iterations = lots is not an integer"})},
        {"", "run --algorithms random-search --problems sphere --iterations " + big_digits + " --out s", 2,
         stderr_says({"mhbench run: iterations = " + excerpt_of_ones + " is too large (at most 1000000000000000)"})},
        {"", "run --algorithms random-search" + tiny_run + " --seed ' -1'", 2,
         stderr_says({"mhbench run: seed =  -1 is not an integer in [0, 2^64)"})},
        {"", "run --algorithms random-search" + tiny_run + " --seed 1e300", 2,
         stderr_says({"mhbench run: seed = 1e300 is not an integer in [0, 2^64)"})},
        {"", "run --algorithms random-search" + tiny_run + " --seeds sometimes", 2,
         stderr_says({"mhbench run: seeds = sometimes is not one of {common, per-algorithm}"})},
        {"", "run --algorithms random-search" + tiny_run + " --threads 0", 2,
         stderr_says({"mhbench run: threads = 0 is outside [1, inf)"})},
        {"", "run --algorithms random-search" + tiny_run + " --target abc", 2,
         stderr_says({"mhbench run: target = abc is not a finite number"})},
        {"", "run --algorithms random-search" + tiny_run + " --relative-target abc", 2,
         stderr_says({"mhbench run: relative-target = abc is not a finite number"})},
        {"", "run --algorithms random-search" + tiny_run + " --target 1e-8 --relative-target 1e-6", 2,
         stderr_says({"mhbench run: give target (f - f* <= E) or relative-target (f - f* <= R x |f*|), not both"})},
        {"", "run --algorithms random-search" + tiny_run + " --relative-target 1e-6", 2,
         stderr_says({"mhbench run: budget: a relative target needs a finite, non-zero f* (it stops at f - f* <= "
               "relative_target x |f*|); problem 'sphere:dim=2' has f* = 0: give target=E instead"})},
        {"", "run --algorithms pso --problems fluxmap:synthetic=on,noise=0.1 --evaluations 100 --relative-target 1e-6 "
             "--out s", 2,
         stderr_says({"mhbench run: budget: a relative target needs a known optimum; problem "
               "'fluxmap:noise=0.1,synthetic=on' has none"})},
        {"", "run --algorithms random-search --problems bbob:f=1,dim=2 --budget evaluations=100,relative_target=-1 "
             "--out s", 2,
         stderr_says({"mhbench run: budget: parameter 'relative_target' = -1 is outside [0, inf]"})},
        {"", "run --algorithms random-search --problems bbob:f=1,dim=2 --budget "
             "evaluations=100,relative_target=1e-6,target=1e-8 --out s", 2,
         stderr_says({"mhbench run: budget 'evaluations=100,relative_target=1e-6,target=1e-8': give target=E "
               "(f - f* <= E) or relative_target=R (f - f* <= R x |f*|), not both"})},
        {"", "run --algorithms random-search --problems sphere --budget iterations=abc --out s", 2,
         one_line("iterations")},
        {"", "run --algorithms random-search --problems sphere --budget bogus=5 --out s", 2,
         one_line("bogus")},
        {"", "run --study nope", 2, one_line("mhbench run: unknown study 'nope'; known: ")},
        {"", "run --study smoke --study-file x.ini --out s", 2,
         stderr_says({"mhbench run: give --study or --study-file, not both"})},

        // ---- run: specs and grids
        {"", "run --algorithms nope" + tiny_run, 2, one_line("mhbench run: unknown algorithm 'nope'; known: ")},
        {"", "run --algorithms random-search --problems nope --iterations 5 --out s", 2,
         one_line("mhbench run: unknown problem 'nope'; known: ")},
        {"", "run --algorithms itlbo:np=1e300" + tiny_run, 2,
         stderr_says({"mhbench run: itlbo: parameter 'np' = 1e300 is too large (at most 100000)"})},
        {"", "run --algorithms itlbo:np=-99999999999999999999" + tiny_run, 2,
         stderr_says({"mhbench run: itlbo: parameter 'np' = -99999999999999999999 is too small (at least 2)"})},
        {"", "run --algorithms itlbo:np=" + big_digits + tiny_run, 2,
         stderr_says({"mhbench run: itlbo: parameter 'np' = " + excerpt_of_ones + " is too large (at most 100000)"})},
        {"", "run --algorithms itlbo:np=1.5" + tiny_run, 2,
         stderr_says({"mhbench run: itlbo: parameter 'np' = 1.5 is not an integer"})},
        {"", "run --algorithms pso:w=" + repeated('x', 100000) + tiny_run, 2,
         stderr_says({"mhbench run: pso: parameter 'w' = 'xxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx...' (100000 characters) "
               "is not a finite number"})},
        {"", "run --algorithms pso:w=2" + tiny_run, 2,
         stderr_says({"mhbench run: pso: parameter 'w' = 2 is outside [0, 1]"})},
        {"", "run --algorithms itlbo:obl=maybe" + tiny_run, 2,
         stderr_says({"mhbench run: itlbo: parameter 'obl' = maybe is not one of on/off, true/false, yes/no, 1/0"})},
        {"", "run --algorithms tlbo:tutorial=on" + tiny_run, 2,
         stderr_says({"mhbench run: tlbo: unknown parameter 'tutorial'; known: np, r"})},
        {"", "run --algorithms :np=5" + tiny_run, 2, one_line("a name is missing (write name:key=value,...)")},
        {"", "run --algorithms itlbo:np" + tiny_run, 2, one_line("np is not key=value")},
        {"", "run --algorithms itlbo:np=5,np=6" + tiny_run, 2, one_line("parameter 'np' is given twice")},
        {"", "run --algorithms itlbo:np=" + tiny_run, 2, one_line("parameter 'np' has no value")},
        {"", "run --algorithms 'it$lbo'" + tiny_run, 2,
         one_line("name 'it$lbo' may only hold letters, digits, '_', '-' and '.'")},
        {"", "run --algorithms 'itlbo:obl={on,off,on}'" + tiny_run, 2,
         one_line("parameter 'obl': value 'on' is listed twice in the set")},
        {"", "run --algorithms random-search --problems 'bbob:f=1-25' --iterations 5 --out s", 2,
         stderr_says({"mhbench run: bbob: parameter 'f' = 25 is outside [1, 24]"})},
        {"", "run --algorithms random-search --problems sphere:dim=0 --iterations 5 --out s", 2,
         stderr_says({"mhbench run: sphere: parameter 'dim' = 0 is outside [1, 10000]"})},
        {"", "run --algorithms 'tlbo tlbo:np=50'" + tiny_run, 2, one_line("tlbo")},

        // ---- run: study files
        {"mkdir d", "run --study-file d --dry-run", 2,
         stderr_says({"mhbench run: d: is a directory, not a study file (try d/study.ini)"})},
        {"", "run --study-file none.ini --dry-run", 2,
         stderr_says({"mhbench run: none.ini: cannot be read (No such file or directory)"})},
        {"printf '\\357\\273\\277algorithms = random-search\\nproblems = sphere:dim=2\\nbudget = iterations=3\\n' > f.ini",
         "run --study-file f.ini --dry-run", 0, stderr_says({})},
        {"printf 'algorithms = random-search\\nproblems = sphere\\niterations = 3\\nthreads = 4\\n' > f.ini",
         "run --study-file f.ini --dry-run", 2,
         stderr_says({"mhbench run: f.ini:4: unknown key 'threads' (it is not part of a study: give --threads on the "
               "command line)"})},
        // Not a study file at all: one line, not one per line of it, and no "no algorithm given".
        {"printf 'garbage\\001 lines\\nmore junk\\n[x\\n\\377\\376\\n' > f.ini", "run --study-file f.ini --dry-run", 2,
         stderr_says({"mhbench run: f.ini: is not a study file (no line is key = value; line 1: 'garbage\\x01 lines' is not "
                      "key = value, and 3 more like it)"})},
        {"printf '[study]\\nalgorithms pso\\nproblems sphere\\n' > f.ini", "run --study-file f.ini --dry-run", 2,
         stderr_says({"mhbench run: f.ini: is not a study file (no line is key = value; line 1: sections ('[study]') are "
                      "not used in study files, and 2 more like it)"})},
        {"printf '[study]\\nalgorithms = random-search\\nproblems = sphere\\niterations = 3\\n' > f.ini",
         "run --study-file f.ini --dry-run", 2,
         stderr_says({"mhbench run: f.ini:1: sections ('[study]') are not used in study files"})},
        {"printf 'algorithms = random-search\\nproblems = sphere\\niterations = 3\\nruns = many\\n' > f.ini",
         "run --study-file f.ini --dry-run", 2, stderr_says({"mhbench run: f.ini:4: runs = many is not an integer"})},
        {"printf 'algorithms = random-search\\nproblems = sphere\\niterations = 3\\nruns = %s\\n' " + big_digits +
             " > f.ini",
         "run --study-file f.ini --dry-run", 2,
         stderr_says({"mhbench run: f.ini:4: runs = " + excerpt_of_ones + " is too large (at most 1000000)"})},
        {"printf 'algorithms = pso:w=2\\nproblems = sphere\\niterations = 3\\n' > f.ini",
         "run --study-file f.ini --dry-run", 2, stderr_says({"mhbench run: f.ini:1: pso: parameter 'w' = 2 is outside [0, 1]"})},
        {"printf 'algorithms = random-search\\nproblems = sphere\\niterations = 3\\niterations = 4\\n' > f.ini",
         "run --study-file f.ini --dry-run", 2, stderr_says({"mhbench run: f.ini:4: 'iterations' is given twice"})},

        // ---- run: output directories
        {"echo x > file", "run --algorithms random-search --problems sphere --iterations 5 --out file/sub", 1,
         stderr_says({"mhbench run: file/sub: cannot create the output directory (Not a directory)"})},
        {"mkdir mine && echo notes > mine/study.ini && echo curves > mine/curves.csv", "run --study smoke --out mine", 1,
         stderr_says({"mhbench run: mine: is not empty and is not a mhbench study (it has no .mhbench-study); its "
               "files are left alone: choose a new or empty --out"})},
        {"", "run --algorithms random-search --problems sphere --iterations 5 --out /sys/mhbench-test", 1,
         one_line("mhbench run: /sys/mhbench-test: cannot create the output directory (")}, // EPERM, EROFS...
        // An unfinished study whose store cannot be read on resume: the OS's reason.
        {study_copy + " && rm s/runs.csv s/store.bin && mkdir s/store.bin",
         "run --study smoke --runs 2 --evaluations 200 --no-report --quiet --out s", 1,
         stderr_says({"mhbench run: s/store.bin: cannot be read (Is a directory)"}), "s"},
        {study_copy, "run --study smoke --runs 2 --evaluations 200 --seed 5 --out s", 1,
         stderr_says({"mhbench run: s: 2 stored runs would change:",
               "  seed = 5, but the stored runs were made with seed = 1",
               "pass --recompute-changed to compute these runs again (keeping every other stored run), "
                  "--overwrite to discard the stored runs and start again, or choose another --out"})},
        // A population the dimension makes too small, or too large for memory: refused before the
        // first run, with no study directory made.
        {"", "run --algorithms lshade:r_ninit=1 --problems sphere:dim=2 --evaluations 100 --runs 2 --quiet --out s", 2,
         stderr_says({"mhbench run: lshade: initial population round(r_ninit * D) = 2 at D = 2 is smaller than n_min = "
                      "4; raise 'r_ninit' (the population is too small)"})},
        {"", "run --algorithms 'lshade:r_ninit=1e4' --problems sphere:dim=10000 --evaluations 100 --out s", 2,
         one_line("mhbench run: lshade: its population at D = 10000 needs 36800 GB for its points alone, more than "
                  "this machine's ")},

        // ---- run: datasets as problems (pmsm:data=FILE)
        {"", "run --algorithms tlbo --problems pmsm:data=none.csv --iterations 2 --out s", 2,
         one_line("none.csv: cannot open the dataset file (No such file or directory)")},
        {dataset_with("5s/^[^,]*,[^,]*/0,1e300/"), "run --algorithms tlbo --problems pmsm:data=d.csv --iterations 2 --out s", 2,
         one_line("d.csv: line 5, column 'ud': 1e300 is outside [-1e9, 1e9]")},
        {dataset_with("s/^\\([^,]*\\),[^,]*/\\1,1e300/;1s/1e300/ud/"),
         "run --algorithms tlbo --problems pmsm:data=d.csv,fitness=direct --iterations 2 --out s", 2,
         one_line("d.csv: line 2, column 'ud': 1e300 is outside [-1e9, 1e9]")},
        {"(grep -v ',[01]$' $F/good.csv; grep ',0$' $F/good.csv | head -n 1; grep ',1$' $F/good.csv | head -n 3) > d.csv",
         "run --algorithms tlbo --problems pmsm:data=d.csv --iterations 2 --out s", 0, stderr_says({}), "s"},

        // ---- simulate
        {"", "simulate", 2, stderr_says({"mhbench simulate: --out FILE is required (see mhbench simulate --help)"})},
        {"", "simulate --out x.csv --samples 501", 2, stderr_says({"mhbench simulate: --samples = 501 is outside [1, 500]"})},
        {"", "simulate --out x.csv --samples 1e300", 2,
         stderr_says({"mhbench simulate: --samples = 1e300 is too large (at most 500)"})},
        {"", "simulate --out x.csv --seed 99999999999999999999", 2,
         stderr_says({"mhbench simulate: --seed = 99999999999999999999 is too large (at most 9223372036854775807)"})},
        {"", "simulate --out x.csv --seed -1", 2,
         stderr_says({"mhbench simulate: --seed = -1 is outside [0, 9223372036854775807]"})},
        {"", "simulate --out x.csv --load abc", 2, stderr_says({"mhbench simulate: --load = abc is not a finite number"})},
        {"", "simulate --out x.csv --speed " + repeated('9', 50000) + "x", 2,
         stderr_says({"mhbench simulate: --speed = '9999999999999999999999999999999999999...' (50001 characters) is not "
               "a finite number"})},
        {"", "simulate --out x.csv --bogus", 2,
         stderr_says({"mhbench simulate: unrecognised option '--bogus' (see mhbench simulate --help)"})},
        {"echo x > file", "simulate --samples 5 --out file/x.csv", 1,
         stderr_says({"mhbench simulate: file/x.csv: cannot be written (Not a directory)"})},
        {"mkdir d", "simulate --samples 5 --out d", 1, stderr_says({"mhbench simulate: d: cannot be written (Is a directory)"})},
        {"", "simulate --samples 5 --out /sys/mhbench-test.csv", 1,
         one_line("mhbench simulate: /sys/mhbench-test.csv: cannot be written (")}, // EACCES here, EROFS in some containers
        {"", "simulate --samples 5 --out /dev/full", 1,
         stderr_says({"mhbench simulate: /dev/full: cannot be written (No space left on device)"})},
        {"", "(trap '' XFSZ; ulimit -f 1; mhbench simulate --samples 50 --out x.csv)", 1,
         stderr_says({"mhbench simulate: x.csv: cannot be written (File too large)"})},

        // ---- identify: options and dataset CSVs
        {"", "identify", 2, stderr_says({"mhbench identify: --data FILE is required (see mhbench identify --help)"})},
        {"", "identify --data none.csv", 1,
         stderr_says({"mhbench identify: none.csv: cannot open the dataset file (No such file or directory)"})},
        {"mkdir d.csv", "identify --data d.csv", 1, stderr_says({"mhbench identify: d.csv: is a directory, not a dataset file"})},
        {"cp $F/good.csv d.csv", "identify --data d.csv --weights 1,2,x,4", 2,
         stderr_says({"mhbench identify: --weights '1,2,x,4': 'x' is not a number >= 0"})},
        {"cp $F/good.csv d.csv", "identify --data d.csv --weights 1,2,3", 2,
         stderr_says({"mhbench identify: --weights '1,2,3' needs four numbers w1,w2,w3,w4"})},
        {"cp $F/good.csv d.csv", "identify --data d.csv --weights 0,0,0,0", 2,
         stderr_says({"mhbench identify: --weights '0,0,0,0': all four are zero, which leaves nothing to fit; give at "
               "least one > 0"})},
        {"cp $F/good.csv d.csv", "identify --data d.csv --id-threshold 0", 2,
         stderr_says({"mhbench identify: --id-threshold = 0 is not a number > 0"})},
        {"printf '\\357\\273\\277' > d.csv && cat $F/good.csv >> d.csv", "identify --data d.csv", 0, stderr_says({})},
        {"printf '\\357\\273\\277t,ud,uq,id,iq,omega,injected\\n' > d.csv && grep -v '^[#t]' $F/good.csv >> d.csv",
         "identify --data d.csv", 0, stderr_says({})},
        {dataset_with("5s/^[^,]*,[^,]*/0,x/"), "identify --data d.csv", 1,
         stderr_says({"mhbench identify: d.csv: line 5, column 'ud': 'x' is not a number"})},
        {dataset_with("5s/^[^,]*,[^,]*/0,nan/"), "identify --data d.csv", 1,
         stderr_says({"mhbench identify: d.csv: line 5, column 'ud': 'nan' is not finite (NaN or infinity)"})},
        {dataset_with("5s/^[^,]*,[^,]*/0,-inf/"), "identify --data d.csv", 1,
         stderr_says({"mhbench identify: d.csv: line 5, column 'ud': '-inf' is not finite (NaN or infinity)"})},
        {dataset_with("5s/^[^,]*,[^,]*/0,1e300/"), "identify --data d.csv", 1,
         stderr_says({"mhbench identify: d.csv: line 5, column 'ud': 1e300 is outside [-1e9, 1e9] (the range of a "
               "dataset value; larger ones would overflow the fit)"})},
        {dataset_with("5s/^[^,]*,[^,]*/0,1e400/"), "identify --data d.csv", 1,
         one_line("d.csv: line 5, column 'ud': 1e400 is outside [-1e9, 1e9]")},
        {dataset_with("5s/,[^,]*$/,-2e9/"), "identify --data d.csv", 1,
         one_line("d.csv: line 5, column 'injected': '-2e9' is not 0 or 1")},
        {"(head -n 4 $F/good.csv; printf '0,'; head -c 1048576 /dev/zero | tr '\\0' 7; printf 'x,';"
         " sed -n 5p $F/good.csv | cut -d, -f3-; tail -n +6 $F/good.csv) > d.csv", "identify --data d.csv", 1,
         stderr_says({"mhbench identify: d.csv: line 5, column 'ud': '7777777777777777777777777777777777777...' "
               "(1048577 characters) is not a number"})},
        {dataset_with("s/^t,ud,/t,vd,/"), "identify --data d.csv", 1,
         stderr_says({"mhbench identify: d.csv: line 1, column 2: unknown column 'vd' (expected "
               "t,ud,uq,id,iq,omega[,injected])"})},
        {dataset_with("s/^t,ud,uq,/t,ud,ud,/"), "identify --data d.csv", 1,
         stderr_says({"mhbench identify: d.csv: line 1, column 3: column 'ud' appears twice"})},
        {dataset_with("s/^t,ud,uq,id,iq,omega,injected/t,ud,uq,id,iq,injected/"), "identify --data d.csv", 1,
         stderr_says({"mhbench identify: d.csv: line 1, column 'omega' is missing from the header (expected "
               "t,ud,uq,id,iq,omega[,injected])"})},
        {dataset_with("6s/,[^,]*$//"), "identify --data d.csv", 1,
         stderr_says({"mhbench identify: d.csv: line 6, row has 6 fields but the header has 7 columns"})},
        {dataset_with("7s/,[01]$/,2/"), "identify --data d.csv", 1,
         stderr_says({"mhbench identify: d.csv: line 7, column 'injected': '2' is not 0 or 1"})},
        {dataset_with("8s/^/# late=1\\n/"), "identify --data d.csv", 1,
         stderr_says({"mhbench identify: d.csv: line 8, metadata line after the header"})},
        {"head -n 3 $F/good.csv > d.csv", "identify --data d.csv", 1,
         stderr_says({"mhbench identify: d.csv: line 3, too few rows: 2 data rows, at least 4 needed"})},
        // Data that cannot determine every parameter get verdicts, not an error
        // (tests/integration/identify_verdicts_test.cpp checks what they say).
        {"grep -v ',1$' $F/good.csv > d.csv", "identify --data d.csv", 0, stderr_says({})},
        {": > d.csv", "identify --data d.csv", 1,
         stderr_says({"mhbench identify: d.csv: no header line (expected t,ud,uq,id,iq,omega[,injected])"})},
        {"(grep -v ',[01]$' $F/good.csv; grep ',0$' $F/good.csv | head -n 1; grep ',1$' $F/good.csv | head -n 3) > d.csv",
         "identify --data d.csv", 0, stderr_says({})},
        {dataset_with("s/,[^,]*,\\([01]\\)$/,0,\\1/"), "identify --data d.csv", 0, stderr_says({})},

        // ---- run: measured flux maps as problems (fluxmap:data=FILE)
        {"", "run --algorithms pso --problems fluxmap:data=none.csv --evaluations 100 --out s", 2,
         stderr_says({"mhbench run: none.csv: cannot be opened (No such file or directory)"})},
        {"mkdir m.csv", "run --algorithms pso --problems fluxmap:data=m.csv --evaluations 100 --out s", 2,
         stderr_says({"mhbench run: m.csv: cannot be read (Is a directory)"})},
        {"printf 'i_d,i_q,psi_d,psi_q\\n1,2,0.1,0.2\\n' > m.csv",
         "run --algorithms pso --problems fluxmap:data=m.csv --evaluations 100 --out s", 2,
         stderr_says({"mhbench run: m.csv: has 1 point, fewer than the model's 14 parameters"})},
        {"printf 'i_d,i_q,psi_d\\n1,2,0.1\\n' > m.csv",
         "run --algorithms pso --problems fluxmap:data=m.csv --evaluations 100 --out s", 2,
         stderr_says({"mhbench run: m.csv: line 1, the header has no column 'psi_q' (a flux map has the columns "
                      "i_d,i_q,psi_d,psi_q)"})},
        {"printf 'i_d,i_q,psi_d,psi_q\\n1,2,0.1,nan\\n' > m.csv",
         "run --algorithms pso --problems fluxmap:data=m.csv --evaluations 100 --out s", 2,
         stderr_says({"mhbench run: m.csv: line 2, column 'psi_q': 'nan' is not finite (NaN or infinity)"})},
        {"", "run --algorithms pso --problems fluxmap:W=-1:2 --evaluations 100 --out s", 2,
         stderr_says({"mhbench run: fluxmap: parameter 'W' = -1:2 needs lo >= 0 (a negative power of a zero flux "
                      "linkage is infinite)"})},
        {"", "run --algorithms pso --problems fluxmap:synthetic=on,truth=1/2/3 --evaluations 100 --out s", 2,
         stderr_says({"mhbench run: fluxmap: parameter 'truth' = 1/2/3 has 3 values; model=pmsyrm has 14 parameters, "
                      "written v1/v2/..."})},

        // ---- identify --flux-map: a measured flux map instead of a PMSM dataset
        {"", "identify --flux-map none.csv", 1,
         stderr_says({"mhbench identify: none.csv: cannot be opened (No such file or directory)"})},
        {"printf 'i_d,i_q,psi_d,psi_q\\n1,2,0.1,nan\\n' > m.csv", "identify --flux-map m.csv", 1,
         stderr_says({"mhbench identify: m.csv: line 2, column 'psi_q': 'nan' is not finite (NaN or infinity)"})},
        {"", "identify --flux-map shipped --model steady", 2,
         stderr_says({"mhbench identify: --model = steady is not a flux-map model; with --flux-map give pmsyrm or syrm"})},
        {"", "identify --flux-map shipped --data d.csv", 2,
         stderr_says({"mhbench identify: --data (a PMSM dataset) and --flux-map are two identifications; give one"})},
        {"", "identify --data d.csv --out o", 2, stderr_says({"mhbench identify: --out applies to --flux-map only"})},
        {"", "identify --flux-map shipped --starts 0", 2,
         stderr_says({"mhbench identify: --starts = 0 is outside [1, 100000]"})},
        {"", "identify --flux-map shipped --bounds S=3:2", 2,
         stderr_says({"mhbench identify: fluxmap: parameter 'S' = 3:2 needs lo < hi"})},
        {"", "identify --flux-map shipped --model syrm --bounds W=1:2", 2,
         stderr_says({"mhbench identify: --bounds 'W=1:2': 'W' is not a parameter of model=syrm (a_d0 a_dd a_q0 "
                      "a_qq a_dq S T U V)"})},
        {"touch o", "identify --flux-map shipped --starts 1 --out o", 1,
         stderr_says({"mhbench identify: --out o: is a file, not a directory"})},

        // ---- eval and points files
        {"", "eval --problem sphere:dim=2", 2, one_line("--points")},
        {"", "eval --problem nope --points p.txt", 2, one_line("mhbench eval: unknown problem 'nope'; known: ")},
        {"echo '1 2' > p.txt", "eval --problem bbob:f=25,dim=2 --points p.txt", 2,
         stderr_says({"mhbench eval: bbob: parameter 'f' = 25 is outside [1, 24]"})},
        {"", "eval --problem sphere:dim=2 --points none.txt", 1, one_line("none.txt: cannot be")},
        {"mkdir p", "eval --problem sphere:dim=2 --points p", 1, stderr_says({"mhbench eval: p: cannot be read (Is a directory)"})},
        {"printf '1 2\\n1 2 3\\n' > p.txt", "eval --problem sphere:dim=2 --points p.txt", 1,
         stderr_says({"mhbench eval: p.txt, line 2: 3 coordinates, but the problem has 2 dimensions"})},
        {"printf '1,2\\n0.5,abc\\n' > p.txt", "eval --problem sphere:dim=2 --points p.txt", 1,
         stderr_says({"mhbench eval: p.txt, line 2, column 5 (coordinate 2): 'abc' is not a finite number"})},
        {"printf '1 nan\\n' > p.txt", "eval --problem sphere:dim=2 --points p.txt", 1,
         stderr_says({"mhbench eval: p.txt, line 1, column 3 (coordinate 2): 'nan' is not a finite number"})},
        {"(printf '1 '; head -c 1048576 /dev/zero | tr '\\0' 5; echo x) > p.txt",
         "eval --problem sphere:dim=2 --points p.txt", 1,
         stderr_says({"mhbench eval: p.txt, line 1, column 3 (coordinate 2): '5555555555555555555555555555555555555...' "
               "(1048577 characters) is not a finite number"})},
        {"printf '\\357\\273\\2771 2\\n' > p.txt", "eval --problem sphere:dim=2 --points p.txt", 0, stderr_says({})},
        // An in-box point where |x| products overflow: +inf is a legal value, never NaN.
        {"echo $(yes 1e11 | head -n 30) > p.txt",
         "eval --problem schwefel_2_22:dim=30,bound=1e12 --points p.txt", 0, stderr_says({})},
        {"", "eval --problem sphere:dim=2 --points - < /dev/null", 1,
         stderr_says({"mhbench eval: standard input: holds no point (one a line, 2 coordinates separated by spaces or "
                      "commas)"})},
        {"printf '# only a comment\\n\\n' > p.txt", "eval --problem sphere:dim=2 --points p.txt", 1,
         stderr_says({"mhbench eval: p.txt: holds no point (one a line, 2 coordinates separated by spaces or commas)"})},

        // ---- plugin-check
        {"", "plugin-check", 2,
         stderr_says({"mhbench plugin-check: give --algorithm SPEC, --problem SPEC or both (see mhbench plugin-check --help)"})},
        {"", "plugin-check --algorithm nope", 2, one_line("mhbench plugin-check: unknown algorithm 'nope'; known: ")},
        {"", "plugin-check --problem sphere:dim=2 --runs 0", 2,
         stderr_says({"mhbench plugin-check: --runs = 0 is outside [1, 1000]"})},

        // ---- report and study directories
        {"", "report", 2, stderr_says({"mhbench report: give the study directory (mhbench report DIR; see --help)"})},
        {"", "report nowhere", 1, stderr_says({"mhbench report: nowhere: is not a directory"})},
        {"mkdir d && echo mine > d/notes.txt", "report d", 1,
         stderr_says({"mhbench report: d: is not a mhbench study directory (no .mhbench-study, study.ini or runs.csv)"})},
        {study_copy + " && rm s/runs.csv", "report s", 1,
         stderr_says({"mhbench report: s: holds an unfinished study (no runs.csv yet); run the same command again to "
               "complete it"})},
        {old_study_copy + " && head -c -7 $F/study/runs.csv > s/runs.csv", "report s --no-figures", 1, one_line("s/runs.csv, line ")},
        {old_study_copy + " && sed -i '2s/,ok,/,maybe,/' s/runs.csv", "report s --no-figures", 1, one_line("s/runs.csv")},
        {old_study_copy + " && sed -i '2s/^0,/zero,/' s/runs.csv", "report s --no-figures", 1,
         stderr_says({"mhbench report: s/runs.csv, line 2, column 'run_id': 'zero' is not an integer"})},
        {old_study_copy + " && head -n 1 $F/study/runs.csv > s/runs.csv", "report s --no-figures", 1,
         stderr_says({"mhbench report: s/runs.csv: has 0 rows, but the study it was rendered for has 2 runs"})},
        // a rendered file that is not what the study wrote (a crash of the machine): refused
        {study_copy + " && sed -i '2s/^0,/zero,/' s/runs.csv", "report s --no-figures", 1,
         one_line("s/runs.csv: is not the file the study wrote (")},
        {study_copy + " && head -c 100 $F/study/curves.csv > s/curves.csv", "report s --no-figures", 1,
         one_line("s/curves.csv: is not the file the study wrote (100 bytes, crc32c ")},
        {study_copy + " && rm s/trajectories.csv", "report s --no-figures", 1, one_line("s/trajectories.csv")},
        // runs.csv must be the one rendered for the study.ini beside it (issue 22)
        {study_copy + " && echo '# edited' >> s/study.ini", "report s --no-figures", 1,
         one_line("s/runs.csv: was rendered for another study.ini than the one beside it (crc32c ")},
        {unmarked_study_copy + " && sed -i '2s/,ok,/,failed,/' s/runs.csv", "report s --no-figures", 1,
         stderr_says({"mhbench report: s/runs.csv, line 2: differs from store.bin's record of run 0" + unmarked_refusal})},
        {unmarked_study_copy + " && sed -i '3s/[.]/.9/' s/curves.csv", "report s --no-figures", 1,
         stderr_says({"mhbench report: s/curves.csv, line 3: differs from store.bin's record of run 0" + unmarked_refusal})},
        {unmarked_study_copy + " && sed -i '$d' s/timings.csv", "report s --no-figures", 1,
         stderr_says({"mhbench report: s/timings.csv, line 3: differs from store.bin's record of run 1" + unmarked_refusal})},
        {unmarked_study_copy + " && sed -i '2s/,random-search,/,pso,/' s/runs.csv", "report s --no-figures", 1,
         one_line("mhbench report: s/runs.csv, line 2: store.bin holds no run pso, sphere:dim=5, evaluations=200, run 0, seed ")},
        {unmarked_study_copy + " && echo '1,5,250,1' >> s/curves.csv", "report s --no-figures", 1,
         stderr_says({"mhbench report: s/curves.csv, line 10: goes on after the last run of runs.csv" + unmarked_refusal})},
        {old_study_copy + " && sed -i '$d' s/runs.csv", "report s --no-figures", 1,
         stderr_says({"mhbench report: s/runs.csv: has 1 row, but the study it was rendered for has 2 runs"})},
        // an error inside finish() leaves no .tmp file (issue 22)
        {study_copy + " && rm s/runs.csv && mkdir s/runs.csv",
         "run --study smoke --runs 2 --evaluations 200 --no-report --quiet --out s", 1,
         one_line("s/runs.csv: cannot be written ("), "s"},
        {study_copy + " && rm s/context.ini", "report s --no-figures", 1,
         stderr_says({"mhbench report: s/context.ini: cannot be read (No such file or directory)"})},
        {study_copy + " && rm s/study.ini && mkdir s/study.ini", "report s --no-figures", 1,
         stderr_says({"mhbench report: s/study.ini: cannot be read (Is a directory)"})},
        {study_copy, "report s --alpha 0 --no-figures", 2, stderr_says({"mhbench report: --alpha = 0 is outside (0, 1)"})},
        {study_copy, "report s --reference cmaes --no-figures", 2, one_line("the study has: ")},
        // the ROPE of the Bayesian signed-rank tests (issue 38): a half-width, never negative or NaN
        {study_copy, "report s --rope -0.5 --no-figures", 2,
         stderr_says({"mhbench report: --rope = -0.5 is outside [0, inf)"})},
        {study_copy, "report s --raw-rope nan --no-figures", 2,
         stderr_says({"mhbench report: --raw-rope = nan is outside [0, inf)"})},
        {"", "run --algorithms random-search" + tiny_run + " --rope -1", 2, one_line("rope = -1 is outside [0, inf)")},
        {study_copy, "report s --format pdf --no-figures", 2,
         stderr_says({"mhbench report: --format: 'pdf' is not one of md, tex, csv"})},
        {"", "run --algorithms random-search" + tiny_run + " --format md,pdf", 2,
         stderr_says({"mhbench run: --format: 'pdf' is not one of md, tex, csv"})},
        {study_copy, "report s --ioh-precision 12 --no-figures", 2,
         stderr_says({"mhbench report: --ioh-precision '12' is not one of ioh, full"})},
        {study_copy, "report s --bogus", 2, stderr_says({"mhbench report: unrecognised option '--bogus' (see mhbench report --help)"})},
        {study_copy, "report s --out s --no-figures", 1,
         stderr_says({"mhbench report: --out s is a study directory, and a report would replace its records; leave "
               "--out out (the report goes to DIR/report) or name a directory of its own"})},
        {study_copy + " && mkdir t && cp s/.mhbench-study t/", "report s --out t --no-figures", 1,
         one_line("mhbench report: --out t is a study directory")},

        // ---- a study directory another process writes (its lock, on the directory, held here by
        // flock(1) on fd 9)
        {study_copy + " && printf 'command = mhbench run\\npid = 1234\\nhost = node7\\nsince = 2026-11-26 "
                      "07:55:01 UTC\\n' > s/.mhbench.lock",
         "(exec 9<s && flock -n 9 && mhbench report s --no-figures)", 1,
         stderr_says({"mhbench report: s is in use by mhbench run (pid 1234 on host node7, since 2026-11-26 07:55:01 "
               "UTC); wait for it, or give --out a directory outside the study"})},
        {study_copy + " && printf 'command = mhbench run\\npid = 1234\\nhost = node7\\nsince = 2026-11-26 "
                      "07:55:01 UTC\\n' > s/.mhbench.lock",
         "(exec 9<s && flock -n 9 && mhbench run --algorithms random-search" + tiny_run + ")", 1,
         stderr_says({"mhbench run: s is in use by mhbench run (pid 1234 on host node7, since 2026-11-26 07:55:01 "
               "UTC); wait for it or use another --out"})},
        // its lock file deleted (or not written yet): the lock on the directory holds all the same
        {study_copy, "(exec 9<s && flock -n 9 && mhbench run --algorithms random-search" + tiny_run + ")", 1,
         stderr_says({"mhbench run: s is in use by another mhbench process; wait for it or use another --out"})},
        {study_copy, "(exec 9<s && flock -n 9 && mhbench report s --no-figures)", 1,
         stderr_says({"mhbench report: s is in use by another mhbench process; wait for it, or give --out a "
               "directory outside the study"})},
        {two_shards + "; mkdir o && : > o/.mhbench.lock", "(exec 9<o && flock -n 9 && mhbench merge o 1 2 --no-report)", 1,
         stderr_says({"mhbench merge: o is in use by another mhbench process; wait for it or choose another OUT"})},
        {study_copy + " && echo x > file", "report s --no-figures --out file/r", 1, one_line("file/r")},
        {study_copy, "(trap '' XFSZ; ulimit -f 1; mhbench report s --no-figures)", 1,
         one_line(": cannot be written (File too large)")},

        // ---- merge
        {two_shards, "merge 1 1 2 --no-report", 2,
         stderr_says({"mhbench merge: OUT 1 is one of the shard directories to merge (1); give another OUT"})},
        {two_shards, "merge ./2 1 2 --no-report --overwrite", 2,
         stderr_says({"mhbench merge: OUT ./2 is one of the shard directories to merge (2); give another OUT"})},
        {two_shards + " && cp -r 1 o", "merge o 1 2 --no-report", 1,
         stderr_says({"mhbench merge: OUT o holds a study (.mhbench-study); pass --overwrite to replace it, or give "
               "another OUT"})},
        {two_shards + " && " + study_copy, "merge s 1 2 --no-report", 1,
         stderr_says({"mhbench merge: OUT s holds a study (.mhbench-study); pass --overwrite to replace it, or give "
               "another OUT"})},
        {two_shards + " && " + study_copy + " && rm s/.mhbench-study", "merge s 1 2 --no-report", 1,
         stderr_says({"mhbench merge: OUT s holds a study (study.ini); pass --overwrite to replace it, or give "
               "another OUT"})},
        {"cp -r $F/shard1 s1 && cp -r $F/shard2 s2", "merge m s1 s2 --no-report", 1,
         mentions("/drive.csv: sha256 ")}, // the file and both hashes (tests/integration/shards_test.cpp)

        // ---- list
        {"", "list nothing", 2, stderr_says({"mhbench list: unknown list 'nothing'; known: algorithms, problems, studies, formats"})},
        {"", "list --bogus", 2, stderr_says({"mhbench list: unrecognised option '--bogus' (see mhbench list --help)"})},
        {"", "list algorithms problems", 2, one_line("mhbench list: ")},
    };
}
// clang-format on

// Launchers of several processes, refused by an mhbench built without MPI (an MPI build makes
// them ranks: tests/mpi/). Single-task jobs of a scheduler run as usual.
std::vector<BadInputCase> launcher_catalogue() {
    const std::string refusal =
        "mhbench run: this mhbench was built without MPI, yet a launcher started it as one of ";
    const std::string advice =
        "which would each run the whole study: run one process (no mpirun, no srun -n N), "
        "or build it with -DMHB_WITH_MPI=ON (the mpi preset)";
    const std::string run = "mhbench run --algorithms random-search" + tiny_run;
    return {
        {"", "(export SLURM_STEP_NUM_TASKS=4 SLURM_NTASKS=4 SLURM_PROCID=0; " + run + ")", 1,
         stderr_says({refusal + "4 processes (SLURM_STEP_NUM_TASKS=4), " + advice})},
        {"", "(export SLURM_PROCID=3; " + run + ")", 1,
         stderr_says({refusal + "at least 4 processes (SLURM_PROCID=3), " + advice})},
        {"", "(export PMIX_RANK=1; " + run + ")", 1,
         stderr_says({refusal + "at least 2 processes (PMIX_RANK=1), " + advice})},
        {"", "(export PMI_SIZE=2 PMI_RANK=0; " + run + ")", 1,
         stderr_says({refusal + "2 processes (PMI_SIZE=2), " + advice})},
        {"", "(export OMPI_COMM_WORLD_SIZE=2; " + run + " --quiet)", 1,
         stderr_says({refusal + "2 processes (OMPI_COMM_WORLD_SIZE=2), " + advice})},
        // sbatch -n 4's batch script, a job-array task: one process each
        {"", "(export SLURM_NTASKS=4 SLURM_PROCID=0 SLURM_JOB_ID=9; " + run + " --quiet)", 0, stderr_says({}),
         "s"},
        {"", "(export SLURM_ARRAY_TASK_ID=2 SLURM_NTASKS=1 SLURM_PROCID=0; " + run + " --quiet)", 0,
         stderr_says({}), "s"},
    };
}

std::vector<BadInputCase> every_case() {
    std::vector<BadInputCase> cases = catalogue();
    if (!mhb::built_with_mpi())
        for (BadInputCase& c : launcher_catalogue())
            cases.push_back(std::move(c));
    return cases;
}

const fs::path bad_inputs_work = mhb::testing_cli::scratch_directory() / "bad_inputs";
const fs::path fixtures = bad_inputs_work / "fixtures";

// Every file under `dir` (relative path -> content), directories as entries of their own.
std::map<std::string, std::string> tree(const fs::path& dir) {
    std::map<std::string, std::string> files;
    std::error_code ec;
    if (!fs::exists(dir, ec))
        return files;
    for (auto it = fs::recursive_directory_iterator(dir, ec); it != fs::recursive_directory_iterator();
         it.increment(ec)) {
        const std::string name = fs::relative(it->path(), dir).string();
        files[name] = it->is_directory() ? "<dir>" : read_text(it->path());
    }
    return files;
}

class BadInputs : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        fs::remove_all(bad_inputs_work);
        fs::create_directories(fixtures);
        const std::string cli = std::string("'") + MHB_CLI_PATH + "'";
        const CliResult dataset =
            mhb::testing_cli::run_shell("cd '" + fixtures.string() + "' && " + cli +
                                        " simulate --samples 10 --out - | grep -v '^#' > good.csv");
        ASSERT_EQ(dataset.exit_code, 0) << dataset.err;
        const CliResult study = mhb::testing_cli::run_shell(
            "cd '" + fixtures.string() + "' && " + cli +
            " run --study smoke --runs 2 --evaluations 200 --no-report --quiet --out study");
        ASSERT_EQ(study.exit_code, 0) << study.err;
        // Two shards of one study that read two contents of drive.csv (regenerated in between).
        const std::string shard = cli + " run --algorithms pso --problems pmsm:data=drive.csv --iterations 2 "
                                        "--runs 2 --no-report --quiet --shard ";
        const CliResult shards = mhb::testing_cli::run_shell(
            "cd '" + fixtures.string() + "' && " + cli + " simulate --out drive.csv && " + shard +
            "1/2 --out shard1 && " + cli + " simulate --load 3 --out drive.csv && " + shard +
            "2/2 --out shard2");
        ASSERT_EQ(shards.exit_code, 0) << shards.err;
    }
};

TEST_F(BadInputs, EveryCaseGivesItsExitCodeAndMessageAndWritesNothing) {
    const auto cases = every_case();
    EXPECT_GE(cases.size(), 70u);
    std::cout << "[ catalogue] " << cases.size() << " cases\n";
    const std::string cli = std::string("'") + MHB_CLI_PATH + "'";
    for (std::size_t k = 0; k < cases.size(); ++k) {
        const BadInputCase& c = cases[k];
        const fs::path dir = bad_inputs_work / ("case_" + std::to_string(k));
        fs::remove_all(dir);
        fs::create_directories(dir);
        const std::string prefix = "cd '" + dir.string() + "' && F='" + fixtures.string() + "' && ";
        if (!c.setup.empty() && mhb::testing_cli::run_shell(prefix + c.setup).exit_code != 0) {
            ADD_FAILURE() << "case " << k << ": the setup failed: " << c.setup.substr(0, 200);
            continue;
        }
        const auto before = tree(dir);
        // `mhbench` as a shell function, so that a case can be a whole command: (ulimit ...; mhbench ...)
        const bool whole = !c.args.empty() && c.args.front() == '(';
        const CliResult r = mhb::testing_cli::run_shell(prefix + "mhbench() { " + cli + " \"$@\"; }; " +
                                                        (whole ? c.args : "mhbench " + c.args));
        const std::string what = "case " + std::to_string(k) + ": mhbench " + c.args.substr(0, 200);
        EXPECT_EQ(r.exit_code, c.exit_code) << what << "\n" << r.err;
        const auto lines = lines_of(r.err);
        switch (c.err.kind) {
        case Stderr::exact_lines:
            EXPECT_EQ(lines, c.err.text) << what;
            break;
        case Stderr::one_line_containing:
            EXPECT_EQ(lines.size(), 1u) << what << "\n" << r.err;
            EXPECT_NE(r.err.find(c.err.text[0]), std::string::npos) << what << "\n" << r.err;
            break;
        case Stderr::containing:
            EXPECT_NE(r.err.find(c.err.text[0]), std::string::npos) << what << "\n" << r.err;
            break;
        }
        for (const auto& line : lines)
            EXPECT_LE(line.size(), 400u) << what << ": a line too long to read";
        if (c.exit_code == 0) {
            EXPECT_EQ(r.out.find("nan"), std::string::npos) << what << ": " << r.out.substr(0, 400);
            continue;
        }
        EXPECT_EQ(r.out, "") << what << ": no output from a failed command";
        // Nothing half-written: the directory holds exactly what it held, byte for byte (but
        // for the one path the case may write, which must hold no report and no .tmp).
        // for the one path a case may write, which must hold no .tmp file, and no report when a
        // study failed).
        auto after = tree(dir);
        for (const auto& [name, content] : after)
            EXPECT_FALSE(name.size() > 4 && name.substr(name.size() - 4) == ".tmp") << what << ": " << name;
        auto unchanged = before;
        if (!c.may_write.empty()) {
            if (fs::path(c.may_write).filename() != "report") {
                EXPECT_FALSE(fs::exists(dir / c.may_write / "report")) << what;
            }
            for (auto* files : {&unchanged, &after})
                for (auto it = files->begin(); it != files->end();)
                    it = it->first.rfind(c.may_write, 0) == 0 ? files->erase(it) : std::next(it);
        }
        EXPECT_EQ(after, unchanged) << what << ": the command changed its directory";
    }
}

} // namespace
