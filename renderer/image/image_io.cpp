#include "renderer/image/image_io.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include <fstream>
#include <stdexcept>
#include <system_error>
#include <unistd.h>

namespace st {
namespace {
namespace fs = std::filesystem;
namespace OIIO = OIIO_NAMESPACE;

// Same folder (rename stays on one file system), same extension (OIIO picks the format by it).
fs::path tempPathFor(const fs::path& file) {
    return file.parent_path() /
           (".tmp-" + std::to_string(::getpid()) + "-" + file.filename().string());
}

void commit(const fs::path& tmp, const fs::path& file) {
    std::error_code ec;
    fs::rename(tmp, file, ec);
    if (ec) {
        fs::remove(tmp, ec);
        throw std::runtime_error(file.string() + ": cannot write: " + ec.message());
    }
}
}  // namespace

void writeImageAtomic(const fs::path& file, const Rgba8Image& img) {
    fs::path tmp = tempPathFor(file);
    OIIO::ImageSpec spec(img.width, img.height, 4, OIIO::TypeDesc::UINT8);
    OIIO::ImageBuf buf(spec, const_cast<std::uint8_t*>(img.pixels.data()));
    if (!buf.write(tmp.string())) {
        std::error_code ec;
        fs::remove(tmp, ec);
        throw std::runtime_error(file.string() + ": cannot write image: " + buf.geterror());
    }
    commit(tmp, file);
}

// Read through ImageInput, not ImageBuf: ImageBuf goes through OIIO's process-wide ImageCache,
// which keeps the first spec it saw for a path, so re-reading a file rewritten in the same
// process (a golden updated, a sweep's chart redrawn) read the new pixels with the old size.
Rgba8Image readImage(const fs::path& file) {
    auto in = OIIO::ImageInput::open(file.string());
    if (!in) throw std::runtime_error(file.string() + ": cannot read image: " + OIIO::geterror());
    const OIIO::ImageSpec spec = in->spec();
    Rgba8Image img{spec.width, spec.height, {}};
    img.pixels.assign(std::size_t(spec.width) * spec.height * 4, 255);
    const int channels = std::min(spec.nchannels, 4);
    if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, img.pixels.data(), 4))
        throw std::runtime_error(file.string() + ": cannot read pixels: " + in->geterror());
    return img;
}

void writeTextAtomic(const fs::path& file, const std::string& text) {
    fs::path tmp = tempPathFor(file);
    {
        std::ofstream out(tmp, std::ios::binary);
        out << text;
        out.flush();
        if (!out) {
            std::error_code ec;
            fs::remove(tmp, ec);
            throw std::runtime_error(file.string() + ": cannot write (folder missing or not writable?)");
        }
    }
    commit(tmp, file);
}

}  // namespace st
