// The record codec as the MPI runner uses it (runner/distribution/mpi/): a record that crosses from a rank to
// the writer comes back exactly, every double bit for bit (NaN payloads, -0.0, infinities), every
// optional set or unset as it was, so that `mpirun -np N mhbench run` writes the bytes one process
// writes. Bytes cut short or left over throw std::runtime_error rather than giving a record.
#include <bit>
#include <cstdint>
#include <gtest/gtest.h>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "results/store/record_codec.hpp"
#include "support/numbers.hpp"

namespace mhb {
namespace {

using mhb::test_support::inf;

double nan_with_payload(std::uint64_t payload) {
    return std::bit_cast<double>(std::uint64_t{0x7ff8000000000000} | payload);
}

::testing::AssertionResult same_bits(const char* a_text, const char* b_text, double a, double b) {
    if (std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b))
        return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure()
           << a_text << " = " << a << " and " << b_text << " = " << b << " differ in their bits";
}

void expect_same_doubles(const std::vector<double>& a, const std::vector<double>& b) {
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i)
        EXPECT_PRED_FORMAT2(same_bits, a[i], b[i]) << "at " << i;
}

void expect_same_optional(const std::optional<double>& a, const std::optional<double>& b) {
    ASSERT_EQ(a.has_value(), b.has_value());
    if (a) {
        EXPECT_PRED_FORMAT2(same_bits, *a, *b);
    }
}

void expect_same(const RunRecord& a, const RunRecord& b) {
    EXPECT_EQ(a.run_id, b.run_id);
    EXPECT_EQ(a.algorithm, b.algorithm);
    EXPECT_EQ(a.problem, b.problem);
    EXPECT_EQ(a.budget, b.budget);
    EXPECT_EQ(a.run_index, b.run_index);
    EXPECT_EQ(a.seed, b.seed);
    EXPECT_EQ(a.ok, b.ok);
    EXPECT_EQ(a.message, b.message);
    EXPECT_PRED_FORMAT2(same_bits, a.best_f, b.best_f);
    expect_same_optional(a.f_opt, b.f_opt);
    expect_same_doubles(a.x_opt, b.x_opt);
    EXPECT_EQ(a.evaluations, b.evaluations);
    EXPECT_EQ(a.iterations, b.iterations);
    EXPECT_EQ(a.evaluations_to_target, b.evaluations_to_target);
    expect_same_doubles(a.best_x, b.best_x);
    EXPECT_EQ(a.parameter_names, b.parameter_names);
    expect_same_doubles(a.true_parameters, b.true_parameters);
    ASSERT_EQ(a.curve.size(), b.curve.size());
    for (std::size_t i = 0; i < a.curve.size(); ++i) {
        EXPECT_EQ(a.curve[i].iteration, b.curve[i].iteration);
        EXPECT_EQ(a.curve[i].evaluations, b.curve[i].evaluations);
        EXPECT_PRED_FORMAT2(same_bits, a.curve[i].best_f, b.curve[i].best_f);
        expect_same_doubles(a.curve[i].best_x, b.curve[i].best_x);
    }
    ASSERT_EQ(a.checkpoints.size(), b.checkpoints.size());
    for (std::size_t i = 0; i < a.checkpoints.size(); ++i) {
        EXPECT_EQ(a.checkpoints[i].evaluations, b.checkpoints[i].evaluations);
        EXPECT_PRED_FORMAT2(same_bits, a.checkpoints[i].best_f, b.checkpoints[i].best_f);
    }
}

// A PMSM-like record: named parameters, a trajectory of best x per iteration, checkpoints, every
// optional set, and the doubles a careless format would lose.
RunRecord full_record() {
    RunRecord r;
    r.run_id = 123456789012;
    r.algorithm = "itlbo:obl=off";
    r.problem = "pmsm:load=2,speed=2500";
    r.budget = "iterations=150,evaluations=20000,target=1e-08";
    r.run_index = 19;
    r.seed = 0xfedcba9876543210U; // above INT64_MAX: the sign bit must survive
    r.best_f = -0.0;
    r.f_opt = 5e-324; // the smallest subnormal
    r.x_opt = {0.365, 0.00325, 0.00575, nan_with_payload(0x123)};
    r.evaluations = 15050;
    r.iterations = 150;
    r.evaluations_to_target = 0;
    r.best_x = {-inf, inf, -0.0, 1.0 / 3.0};
    r.parameter_names = {"Rs", "Ld", "", "psi f, \"quoted\"\nnewline \xc3\xa9"};
    r.true_parameters = {0.365, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::max(),
                         std::numeric_limits<double>::lowest()};
    for (std::int64_t i = 0; i < 4; ++i)
        r.curve.push_back(
            {i,
             50 + 100 * i,
             1.0 / static_cast<double>(i + 1),
             {static_cast<double>(i), -0.0, nan_with_payload(static_cast<std::uint64_t>(i)), inf}});
    r.curve.push_back({4, 450, -inf, {}}); // a point without best_x
    r.checkpoints = {{100, nan_with_payload(7)}, {1000, -0.0}, {10000, 2.5e-300}};
    return r;
}

RunRecord failed_record() {
    RunRecord r;
    r.run_id = 0;
    r.algorithm = "nlopt:algorithm=LN_BOBYQA";
    r.problem = "sphere:dim=5";
    r.ok = false;
    r.message = "nlopt: bounds are inconsistent"; // best_f stays NaN, every vector empty
    return r;
}

TEST(RecordCodec, AFullRecordComesBackBitForBit) {
    const RunRecord original = full_record();
    const DecodedRecord back = decode_record(encode_record(original, 12.75));
    expect_same(back.record, original);
    EXPECT_EQ(back.wall_seconds, 12.75);
}

TEST(RecordCodec, AFailedRecordWithEmptyCurvesAndUnsetOptionalsComesBack) {
    const RunRecord original = failed_record();
    ASSERT_FALSE(original.f_opt);
    ASSERT_FALSE(original.evaluations_to_target);
    const DecodedRecord back = decode_record(encode_record(original, -0.0));
    expect_same(back.record, original);
    EXPECT_FALSE(back.record.f_opt);
    EXPECT_FALSE(back.record.evaluations_to_target);
    EXPECT_TRUE(back.record.curve.empty());
    EXPECT_TRUE(back.record.checkpoints.empty());
    EXPECT_PRED_FORMAT2(same_bits, back.wall_seconds, -0.0);
}

TEST(RecordCodec, OptionalsHoldingZeroAreSetAndTheirAbsenceIsUnset) {
    RunRecord zero = failed_record();
    zero.f_opt = 0.0;
    zero.evaluations_to_target = 0;
    const RunRecord back = decode_record(encode_record(zero, 0.0)).record;
    ASSERT_TRUE(back.f_opt);
    EXPECT_PRED_FORMAT2(same_bits, *back.f_opt, 0.0);
    ASSERT_TRUE(back.evaluations_to_target);
    EXPECT_EQ(*back.evaluations_to_target, 0);
}

TEST(RecordCodec, EncodingIsDeterministicAndRecordsFollowEachOtherInOneStream) {
    EXPECT_EQ(encode_record(full_record(), 1.0), encode_record(full_record(), 1.0));
    ByteWriter out;
    encode_record(out, full_record(), 1.0);
    encode_record(out, failed_record(), 2.0);
    ByteReader in(out.bytes(), "stream");
    expect_same(decode_record(in).record, full_record());
    const DecodedRecord second = decode_record(in);
    expect_same(second.record, failed_record());
    EXPECT_EQ(second.wall_seconds, 2.0);
    EXPECT_TRUE(in.at_end());
}

TEST(RecordCodec, EveryTruncationThrowsRuntimeError) {
    for (const RunRecord& record : {full_record(), failed_record()}) {
        const std::string bytes = encode_record(record, 3.0);
        for (std::size_t n = 0; n < bytes.size(); ++n)
            EXPECT_THROW((void)decode_record(std::string_view(bytes).substr(0, n)), std::runtime_error)
                << n << " of " << bytes.size() << " bytes";
    }
}

TEST(RecordCodec, BytesLeftOverOrAnAbsurdLengthThrowRuntimeError) {
    EXPECT_THROW((void)decode_record(encode_record(failed_record(), 1.0) + "x"), std::runtime_error);
    // A string length near 2^64 where the algorithm name's length belongs: an error, not an
    // allocation of that size.
    std::string bytes = encode_record(failed_record(), 1.0);
    for (std::size_t i = 8; i < 16; ++i)
        bytes[i] = '\xff';
    EXPECT_THROW((void)decode_record(bytes), std::runtime_error);
}

} // namespace
} // namespace mhb
