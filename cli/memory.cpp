#include "memory.hpp"

#include <cmath>

namespace exidel::cli {

namespace {

struct Need {
    std::string what;
    std::size_t points = 0;
    double bytes = 0;
};

Need& current() {
    static Need need;
    return need;
}

}  // namespace

void note_memory_need(std::string_view what, std::size_t points, double bytes) {
    Need& n = current();
    n.what.assign(what);
    n.points = points;
    n.bytes = bytes;
}

std::string out_of_memory_message() {
    const Need& n = current();
    if (n.what.empty()) return "not enough memory";
    std::string message = "not enough memory for ";
    message.append(n.what);
    if (n.points > 0) {
        message.append(" ").append(std::to_string(n.points)).append(" points");
    }
    if (n.bytes > 0) {
        const auto mb = static_cast<long long>(std::ceil(n.bytes / 1e6));
        message.append(" (needs about ").append(std::to_string(mb)).append(" MB)");
    }
    return message;
}

}  // namespace exidel::cli
