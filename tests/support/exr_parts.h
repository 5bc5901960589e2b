#pragma once
// The parts of an OpenEXR file read by OpenEXR's own reader, every channel as float.
#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputPart.h>
#include <OpenEXR/ImfMultiPartInputFile.h>

namespace fg::test {

// One part of an EXR file, every channel as float (OpenEXR converts half).
struct ExrPartPixels {
    Imf::Header header;
    int width = 0, height = 0;
    std::map<std::string, std::vector<float>> channels;
    float at(const std::string& c, int x, int y) const { return channels.at(c)[static_cast<std::size_t>(y * width + x)]; }
};

// Every channel, or only those named in `only`.
inline std::vector<ExrPartPixels> read_exr(const std::string& file, const std::vector<std::string>& only = {}) {
    Imf::MultiPartInputFile in(file.c_str());
    std::vector<ExrPartPixels> parts;
    for (int i = 0; i < in.parts(); ++i) {
        Imf::InputPart part(in, i);
        ExrPartPixels p;
        p.header = part.header();
        const Imath::Box2i window = p.header.dataWindow();
        p.width = window.max.x - window.min.x + 1;
        p.height = window.max.y - window.min.y + 1;
        Imf::FrameBuffer fb;
        for (auto c = p.header.channels().begin(); c != p.header.channels().end(); ++c) {
            if (!only.empty() && std::find(only.begin(), only.end(), c.name()) == only.end()) continue;
            auto& v = p.channels[c.name()];
            v.resize(static_cast<std::size_t>(p.width * p.height));
            fb.insert(c.name(), Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(v.data()), sizeof(float),
                                           sizeof(float) * static_cast<std::size_t>(p.width)));
        }
        part.setFrameBuffer(fb);
        part.readPixels(window.min.y, window.max.y);
        parts.push_back(std::move(p));
    }
    return parts;
}

}  // namespace fg::test
