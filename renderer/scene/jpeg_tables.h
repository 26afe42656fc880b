#pragma once
// A guard for Debian's stb_image 2.27, which trusts the 16 code counts of a JPEG Huffman table
// (DHT segment): counts summing above 256 write past its 256-entry arrays. Found by fuzzing
// (tests/fuzz/crashes/gltf/stb-jpeg-dht-overflow.gltf); upstream stb_image 2.28 refuses such
// tables itself. Pure bytes in, no decoding.
#include <cstddef>
#include <cstdint>

namespace st {

// False when `bytes` is a JPEG (starts with SOI) holding a Huffman table with more than 256 codes;
// true for any other input, including JPEGs too broken for stb to get that far.
bool jpegHuffmanTablesFit(const std::uint8_t* bytes, std::size_t size);

}  // namespace st
