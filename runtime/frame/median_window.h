#pragma once
// The median of the last n frame times: one slow frame (a pipeline compile, the OS) is not a
// trend. The governor and dynamic resolution judge GPU time through it.
#include <algorithm>
#include <cstddef>
#include <deque>
#include <vector>

namespace fg {

class MedianWindow {
public:
    explicit MedianWindow(int size) : size_(static_cast<std::size_t>(std::max(1, size))) {}

    void push(double value) {
        values_.push_back(value);
        if (values_.size() > size_) values_.pop_front();
    }
    bool full() const { return values_.size() == size_; }
    double median() const {
        std::vector<double> sorted(values_.begin(), values_.end());
        const auto middle = sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2);
        std::nth_element(sorted.begin(), middle, sorted.end());
        return *middle;
    }
    void clear() { values_.clear(); }

private:
    std::size_t size_;
    std::deque<double> values_;
};

}  // namespace fg
