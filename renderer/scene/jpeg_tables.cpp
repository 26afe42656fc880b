#include "renderer/scene/jpeg_tables.h"

namespace st {
namespace {

// Reads as stb_image's stbi__get8 does: zero past the end.
struct Reader {
    const std::uint8_t* bytes;
    std::size_t size;
    std::size_t at;
    int next() { return at < size ? bytes[at++] : (at++, 0); }
};

// One DHT segment's payload, table by table, in stb_image's order (stbi__process_marker, case 0xC4).
bool segmentFits(Reader r, long length) {
    while (length > 0) {
        r.next();  // table class and id
        long codes = 0;
        for (int i = 0; i < 16; ++i) codes += r.next();
        if (codes > 256) return false;
        r.at += static_cast<std::size_t>(codes);
        length -= 17 + codes;
    }
    return true;
}

bool hasNoLength(std::uint8_t marker) {
    return marker == 0x00 || marker == 0x01 || (marker >= 0xD0 && marker <= 0xD7);  // stuffing, TEM, RSTn
}

}  // namespace

bool jpegHuffmanTablesFit(const std::uint8_t* bytes, std::size_t size) {
    if (size < 2 || bytes[0] != 0xFF || bytes[1] != 0xD8) return true;
    // Every marker is visited: segments are skipped by their length, and entropy-coded data (after
    // SOS) byte by byte, where 0xFF is always followed by 0x00 or a marker.
    std::size_t i = 2;
    while (i + 1 < size) {
        const std::uint8_t marker = bytes[i + 1];
        if (bytes[i] != 0xFF || marker == 0xFF) {
            ++i;
        } else if (hasNoLength(marker)) {
            i += 2;
        } else if (marker == 0xD9 || i + 3 >= size) {
            return true;  // end of image, or truncated: stb stops there too
        } else {
            const std::size_t length = std::size_t(bytes[i + 2]) << 8 | bytes[i + 3];
            if (marker == 0xC4 && !segmentFits(Reader{bytes, size, i + 4}, long(length) - 2)) return false;
            i += 2 + length;
        }
    }
    return true;
}

}  // namespace st
