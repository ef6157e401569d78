// exidel: the names of the location kinds (locate.hpp), with the kernel-independent core.
#include "exidel/delaunay/locate.hpp"

namespace exidel::delaunay {

std::string_view to_string(LocationKind kind) noexcept {
    switch (kind) {
        case LocationKind::inside: return "inside";
        case LocationKind::on_edge: return "on_edge";
        case LocationKind::on_vertex: return "on_vertex";
        case LocationKind::outside: return "outside";
    }
    return "unknown";
}

}  // namespace exidel::delaunay
