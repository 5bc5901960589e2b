#include "studio/edit_queue.h"

namespace fg::studio {

EditQueue::EditQueue(Compile compile) : compile_(std::move(compile)), worker_([this] { work(); }) {}

EditQueue::~EditQueue() {
    {
        std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_all();
    worker_.join();
}

std::uint64_t EditQueue::submit(std::string graph_text) {
    std::uint64_t revision;
    {
        std::lock_guard lock(mutex_);
        revision = next_revision_++;
        if (waiting_) ++skipped_;
        waiting_ = std::make_pair(revision, std::move(graph_text));
    }
    wake_.notify_one();
    return revision;
}

void EditQueue::work() {
    std::unique_lock lock(mutex_);
    while (true) {
        wake_.wait(lock, [&] { return stopping_ || waiting_; });
        if (stopping_) return;
        auto [revision, text] = std::move(*waiting_);
        waiting_.reset();
        compiling_ = true;
        lock.unlock();
        EditOutcome outcome;
        try {
            outcome = compile_(text, revision);
        } catch (const std::exception& e) {
            outcome.ok = false;
            outcome.diagnostics = nlohmann::json::array({{{"severity", "error"}, {"message", e.what()}, {"pointer", ""},
                                                          {"node", ""}, {"context", ""}, {"text", e.what()}}});
        }
        outcome.revision = revision;
        lock.lock();
        compiling_ = false;
        latest_ = std::move(outcome);
        done_.notify_all();
    }
}

EditOutcome EditQueue::wait_for(std::uint64_t revision, std::chrono::milliseconds timeout) {
    std::unique_lock lock(mutex_);
    done_.wait_for(lock, timeout, [&] { return latest_.revision >= revision; });
    return latest_;
}

EditOutcome EditQueue::latest() const {
    std::lock_guard lock(mutex_);
    return latest_;
}

std::uint64_t EditQueue::submitted() const {
    std::lock_guard lock(mutex_);
    return next_revision_ - 1;
}

std::uint64_t EditQueue::skipped() const {
    std::lock_guard lock(mutex_);
    return skipped_;
}

bool EditQueue::busy() const {
    std::lock_guard lock(mutex_);
    return compiling_ || waiting_.has_value();
}

}  // namespace fg::studio
