// exidel proofs: checks every error-bound constant of predicates/ against the value the
// proofs establish (proofs/README.md). The proven values come from the file that
// proofs/derive_bounds.py writes from Gappa's output; the code's values come from
// constants.hpp itself (included, so the compiler reads the real ones) and, for the range
// limits that live in adaptive.cpp, from that source file.
//
// Usage: check_constants BOUNDS_FILE ADAPTIVE_CPP CONSTANTS_HPP
// Exit code 0 iff every claim holds, every constant has a claim, and every
// `inline constexpr double` of constants.hpp (but epsilon) is in the list below.
// A claim marked `if=CONDITION` is proven only if that unproven statement (proofs/bounds.md)
// holds: it is checked like the others, and reported as conditional.
#include <boost/multiprecision/cpp_int.hpp>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "exidel/predicates/constants.hpp"

namespace {

using Rational = boost::multiprecision::cpp_rational;

// Every constant of constants.hpp that is an error bound or a hypothesis of one. A new
// constant must be added here and get a claim, or the check fails (no silent drift).
std::map<std::string, Rational> code_constants() {
    namespace b = exidel::bounds;
    // cpp_rational(double) is exact: a double is a dyadic rational.
    return {
        {"ccw_a", Rational(b::ccw_a)},
        {"ccw_b", Rational(b::ccw_b)},
        {"ccw_c", Rational(b::ccw_c)},
        {"result_err", Rational(b::result_err)},
        {"icc_a", Rational(b::icc_a)},
        {"icc_b", Rational(b::icc_b)},
        {"icc_c", Rational(b::icc_c)},
        {"icc_dw", Rational(b::icc_dw)},
        {"icc_dw_min", Rational(b::icc_dw_min)},
        {"icc_dw_max", Rational(b::icc_dw_max)},
        {"icc_static", Rational(b::icc_static)},
        {"icc_static_min", Rational(b::icc_static_min)},
        {"icc_static_max", Rational(b::icc_static_max)},
        {"underflow_orient", Rational(b::underflow_orient)},
        {"underflow_incircle", Rational(b::underflow_incircle)},
        {"cos_rel", Rational(b::cos_rel)},
        {"cos_rel_dot", Rational(b::cos_rel_dot)},
        {"cos_max_dot_rel", Rational(b::cos_max_dot_rel)},
        {"cos_min_factor", Rational(b::cos_min_factor)},
        {"cos_dw", Rational(b::cos_dw)},
        {"cos_dw_min", Rational(b::cos_dw_min)},
        {"cos_dw_max", Rational(b::cos_dw_max)},
        {"dist_a", Rational(b::dist_a)},
        {"underflow_dist", Rational(b::underflow_dist)},
        {"radial_key_rel", Rational(b::radial_key_rel)},
        {"radial_key_min", Rational(b::radial_key_min)},
        {"radial_key_max", Rational(b::radial_key_max)},
        {"circumcenter_rel", Rational(b::circumcenter_rel)},
        {"circumcenter_float_rel", Rational(b::circumcenter_float_rel)},
        // A factor 1 + f: the proof claims its excess f (bounds.md#circumcenter, F2).
        {"circumcenter_float_factor", Rational(b::circumcenter_float_factor) - 1},
        {"circumcenter_margin", Rational(b::circumcenter_margin)},
        {"circumcenter_min_scale", Rational(b::circumcenter_min_scale)},
        {"circumcenter_max_scale", Rational(b::circumcenter_max_scale)},
        {"circumcenter_min_part", Rational(b::circumcenter_min_part)},
        {"circumcenter_min_offset", Rational(b::circumcenter_min_offset)},
        {"circumcenter_max_offset", Rational(b::circumcenter_max_offset)},
    };
}

std::string read_file(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot open " + path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// The range limits of adaptive.cpp: `constexpr int orient_max_log = 500;` and the degree
// passed beside each in `expansion_safe({...}, 2, orient_max_log)`.
void add_range_limits(const std::string& source, std::map<std::string, Rational>& values) {
    const std::regex limit(R"(constexpr\s+int\s+(\w+_max_log)\s*=\s*(\d+)\s*;)");
    for (std::sregex_iterator it(source.begin(), source.end(), limit), end; it != end; ++it) {
        values[(*it)[1]] = Rational((*it)[2].str());
    }
    const std::regex call(R"(expansion_safe\(\{[^}]*\},\s*(\d+),\s*(\w+)_max_log\))");
    for (std::sregex_iterator it(source.begin(), source.end(), call), end; it != end; ++it) {
        values[(*it)[2].str() + "_degree"] = Rational((*it)[1].str());
    }
}

// The list in code_constants() is written by hand; this makes sure it is complete.
int unlisted_constants(const std::string& header, const std::map<std::string, Rational>& values) {
    const std::regex declaration(R"(inline\s+constexpr\s+double\s+(\w+)\s*=)");
    int missing = 0;
    for (std::sregex_iterator it(header.begin(), header.end(), declaration), end; it != end;
         ++it) {
        const std::string name = (*it)[1];
        if (name != "epsilon" && !values.contains(name)) {
            std::cout << "FAIL " << name << ": in constants.hpp but not checked by "
                      << "check_constants.cpp (add it to code_constants() and give it a proof)\n";
            ++missing;
        }
    }
    return missing;
}

std::string show(const Rational& r) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.17g", r.convert_to<double>());
    return buf;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 4) {
        std::cerr << "usage: check_constants BOUNDS_FILE ADAPTIVE_CPP CONSTANTS_HPP\n";
        return 2;
    }
    try {
        std::map<std::string, Rational> values = code_constants();
        add_range_limits(read_file(argv[2]), values);

        std::istringstream bounds(read_file(argv[1]));
        std::set<std::string> claimed;
        std::map<std::string, std::set<std::string>> conditional;  // constant -> conditions
        int failures = unlisted_constants(read_file(argv[3]), values);
        std::string line;
        while (std::getline(bounds, line)) {
            if (line.empty() || line[0] == '#') continue;
            std::istringstream fields(line);
            std::string name, kind, value, condition, extra;
            if (!(fields >> name >> kind >> value) || (kind != "min" && kind != "max")) {
                throw std::runtime_error("malformed line in bounds file: " + line);
            }
            if (fields >> condition) {
                const bool bad = condition.rfind("if=", 0) != 0 || condition.size() == 3;
                if (bad || (fields >> extra)) {
                    throw std::runtime_error("malformed line in bounds file: " + line);
                }
                condition = condition.substr(3);
            }
            const Rational proven(value);
            const auto found = values.find(name);
            if (found == values.end()) {
                std::cout << "FAIL " << name << ": proven, but not found in the code\n";
                ++failures;
                continue;
            }
            claimed.insert(name);
            const Rational& code = found->second;
            const bool ok = kind == "min" ? code >= proven : code <= proven;
            if (!condition.empty()) conditional[name].insert(condition);
            std::cout << (ok ? "ok   " : "FAIL ") << name << " = " << show(code)
                      << (kind == "min" ? " >= " : " <= ") << show(proven)
                      << (condition.empty() ? " (proven"
                                            : " (proven if " + condition + " holds")
                      << (ok ? "" : "; the code's value is outside the proven range, by "
                                        + show(abs(proven - code) / proven) + " relative")
                      << ")\n";
            failures += ok ? 0 : 1;
        }
        for (const auto& [name, code] : values) {
            if (!claimed.contains(name)) {
                std::cout << "FAIL " << name << " = " << show(code) << ": no proof claims it\n";
                ++failures;
            }
        }
        if (failures != 0) {
            std::cout << "constants NOT proven\n";
        } else if (conditional.empty()) {
            std::cout << "all constants proven\n";
        } else {
            std::cout << "all claims hold; proven only under an unproven condition "
                         "(proofs/bounds.md):";
            const char* separator = " ";
            for (const auto& [name, conditions] : conditional) {
                for (const auto& c : conditions) {
                    std::cout << separator << name << " (" << c << ")";
                    separator = ", ";
                }
            }
            std::cout << "\n";
        }
        return failures == 0 ? 0 : 1;
    } catch (const std::exception& error) {
        std::cerr << "check_constants: " << error.what() << "\n";
        return 2;
    }
}
