// exidel I/O: the parallel writer every text format goes through (lib/io/src/text.hpp,
// write_slices): the same bytes for every thread count and slice size, however unevenly
// the slices take to format, and an exception from a format call or from the stream reaches
// the caller without a hang.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <ios>
#include <sstream>
#include <stdexcept>
#include <streambuf>
#include <string>
#include <thread>

#include "text.hpp"

namespace {

using exidel::io::detail::TextBuffer;
using exidel::io::detail::write_slices;

// Item i as "i;" (a text whose every byte says where it belongs).
void format_items(std::size_t begin, std::size_t end, TextBuffer& b) {
    for (std::size_t i = begin; i < end; ++i) {
        b.append(24, [&](char* p) {
            p = std::to_chars(p, p + 20, i).ptr;
            *p++ = ';';
            return p;
        });
    }
}

std::string expected_text(std::size_t count) {
    TextBuffer b;
    format_items(0, count, b);
    return std::string(b.view());
}

TEST(WriteSlices, SameBytesForEveryThreadCountAndSliceSize) {
    // Many more slices than the ring of 2 x threads buffers, so that every buffer is
    // reused; slices whose index is a multiple of 5 sleep, so that later slices finish
    // first and wait for their turn to be written.
    for (const std::size_t count : {0u, 1u, 7u, 1000u, 4099u}) {
        const std::string want = expected_text(count);
        for (const std::size_t slice : {1u, 3u, 64u, 5000u}) {
            for (const unsigned threads : {0u, 1u, 2u, 3u, 8u}) {
                std::ostringstream out;
                write_slices(out, count, threads, slice,
                             [&](std::size_t begin, std::size_t end, TextBuffer& b) {
                                 if ((begin / slice) % 5 == 0 && count <= 1000) {
                                     std::this_thread::sleep_for(std::chrono::microseconds(50));
                                 }
                                 format_items(begin, end, b);
                             });
                EXPECT_EQ(out.str(), want)
                    << "count " << count << " slice " << slice << " threads " << threads;
            }
        }
    }
}

TEST(WriteSlices, AFormatCallThatThrowsStopsEveryThread) {
    // Slice 40 of 400 throws: the call returns (no thread is left waiting for a slice that
    // will never be written) with that exception, and what was written is whole slices in
    // order, none past the failed one.
    const std::string want = expected_text(400);
    for (const unsigned threads : {1u, 2u, 4u, 8u}) {
        std::ostringstream out;
        std::atomic<int> calls{0};
        EXPECT_THROW(write_slices(out, 400, threads, 1,
                                  [&](std::size_t begin, std::size_t end, TextBuffer& b) {
                                      ++calls;
                                      if (begin == 40) throw std::runtime_error("slice 40");
                                      format_items(begin, end, b);
                                  }),
                     std::runtime_error)
            << threads;
        const std::string got = out.str();
        EXPECT_LE(got.size(), expected_text(40).size()) << threads;
        EXPECT_EQ(want.compare(0, got.size(), got), 0) << threads;
        // No thread formats more than the ring's 2 x threads slices beyond the failure.
        EXPECT_LE(calls.load(), 41 + 2 * static_cast<int>(threads)) << threads;
    }
}

// A stream buffer that takes `room` bytes and then fails, as a full disk does.
class FullAfter : public std::streambuf {
public:
    explicit FullAfter(std::size_t room) : room_(room) {}
    std::string text;

protected:
    std::streamsize xsputn(const char* s, std::streamsize n) override {
        const auto take = std::min<std::size_t>(static_cast<std::size_t>(n), room_ - text.size());
        text.append(s, take);
        return static_cast<std::streamsize>(take);
    }
    int_type overflow(int_type c) override {
        if (traits_type::eq_int_type(c, traits_type::eof()) || text.size() == room_) {
            return traits_type::eof();
        }
        text.push_back(traits_type::to_char_type(c));
        return c;
    }

private:
    std::size_t room_;
};

TEST(WriteSlices, AStreamThatFailsStopsEveryThread) {
    const std::string want = expected_text(3000);
    for (const unsigned threads : {1u, 2u, 5u}) {
        // With exceptions enabled the failed write throws out of the call.
        {
            FullAfter full(1000);
            std::ostream out(&full);
            out.exceptions(std::ios::badbit);
            EXPECT_THROW(write_slices(out, 3000, threads, 10, format_items), std::ios::failure)
                << threads;
            EXPECT_EQ(full.text, want.substr(0, 1000)) << threads;
        }
        // Without, the stream is left bad and the call returns; the caller checks it.
        {
            FullAfter full(1000);
            std::ostream out(&full);
            write_slices(out, 3000, threads, 10, format_items);
            EXPECT_TRUE(out.bad()) << threads;
            EXPECT_EQ(full.text, want.substr(0, 1000)) << threads;
        }
    }
}

}  // namespace
