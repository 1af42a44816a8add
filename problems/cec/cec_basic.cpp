// What the basic functions compute once: names, the Weierstrass tables, each BasicShape's constants.
#include "problems/cec/cec_basic.hpp"

#include <stdexcept>
#include <string>

namespace mhb::cec {

std::string_view basic_name(Basic basic) {
    switch (basic) {
    case Basic::bent_cigar:
        return "Bent Cigar";
    case Basic::sum_of_different_power:
        return "Sum of Different Power";
    case Basic::zakharov:
        return "Zakharov";
    case Basic::rosenbrock:
        return "Rosenbrock";
    case Basic::rastrigin:
        return "Rastrigin";
    case Basic::schaffer_f7:
        return "Schaffer F7";
    case Basic::lunacek_bi_rastrigin:
        return "Lunacek bi-Rastrigin";
    case Basic::levy_2017:
    case Basic::levy_2022:
        return "Levy";
    case Basic::schwefel:
        return "Schwefel";
    case Basic::ellipsoid:
        return "High Conditioned Elliptic";
    case Basic::discus:
        return "Discus";
    case Basic::ackley:
        return "Ackley";
    case Basic::weierstrass:
        return "Weierstrass";
    case Basic::griewank:
        return "Griewank";
    case Basic::katsuura:
        return "Katsuura";
    case Basic::happycat:
        return "HappyCat";
    case Basic::hgbat:
        return "HGBat";
    case Basic::griewank_rosenbrock:
        return "Expanded Griewank plus Rosenbrock";
    case Basic::expanded_schaffer_f6:
        return "Expanded Schaffer F6";
    }
    return "?";
}

namespace detail {

const WeierstrassTables& weierstrass_tables() {
    static const WeierstrassTables tables = [] {
        WeierstrassTables t;
        const double a = 0.5;
        const double b = 3.0;
        for (int k = 0; k < weierstrass_terms; ++k) {
            const auto i = static_cast<std::size_t>(k);
            t.a_k[i] = std::pow(a, k);
            t.b_k[i] = std::pow(b, k);
            t.constant += t.a_k[i] * std::cos(2.0 * pi * t.b_k[i] * 0.5);
        }
        return t;
    }();
    return tables;
}

} // namespace detail

BasicShape::BasicShape(Basic basic, int n, const double* shift)
    : basic_(basic), n_(n), scale_(basic_scale(basic)) {
    if (n < 1)
        throw std::logic_error("cec: " + std::string(basic_name(basic)) + " on " + std::to_string(n) +
                               " coordinates");
    const auto size = static_cast<std::size_t>(n);
    switch (basic) {
    case Basic::ellipsoid:
        table_.resize(size);
        for (int i = 0; i < n; ++i)
            table_[static_cast<std::size_t>(i)] = std::pow(10.0, 6.0 * i / (n - 1));
        break;
    case Basic::griewank:
        table_.resize(size);
        for (int i = 0; i < n; ++i)
            table_[static_cast<std::size_t>(i)] = std::sqrt(1.0 + i);
        break;
    case Basic::katsuura:
        c0_ = 10.0 / std::pow(1.0 * n, 1.2);
        c1_ = 10.0 / n / n;
        break;
    case Basic::lunacek_bi_rastrigin: {
        if (shift == nullptr)
            throw std::logic_error("cec: Lunacek bi-Rastrigin needs the shift vector for its signs");
        table_.resize(size);
        for (int i = 0; i < n; ++i)
            table_[static_cast<std::size_t>(i)] = shift[i] < 0.0 ? -1.0 : 1.0;
        const double mu0 = 2.5;
        const double d = 1.0;
        c0_ = 1.0 - 1.0 / (2.0 * std::pow(n + 20.0, 0.5) - 8.2);
        c1_ = -std::pow((mu0 * mu0 - d) / c0_, 0.5);
        break;
    }
    case Basic::levy_2017:
        c0_ = 1.0;
        break;
    case Basic::levy_2022:
        c0_ = 0.0;
        break;
    default:
        break;
    }
}

} // namespace mhb::cec
