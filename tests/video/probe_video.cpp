// For the CLI tests: prints "FRAMES WIDTHxHEIGHT FPS CODEC" of a movie, decoded with FFmpeg's libraries.
#include <iostream>

#include "tstyles/core/errors.h"
#include "tstyles/video/video_file.h"

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: probe_video MOVIE\n";
        return 2;
    }
    try {
        const tstyles::VideoInfo info = tstyles::probeVideo(argv[1]);
        std::cout << info.frameCount << " " << info.width << "x" << info.height << " " << info.framesPerSecond << " "
                  << info.codecName << "\n";
    } catch (const tstyles::InputError& error) {
        std::cerr << error.what() << "\n";
        return 2;
    }
    return 0;
}
