#pragma once
// A distributed run inside one process, for tests: each rank is a thread, and the ranks
// exchange through shared memory (checker/collective.hpp), so the distributed checks can
// be compared with one process's under the sanitizers, without mpirun.

#include <algorithm>
#include <barrier>
#include <functional>
#include <thread>
#include <vector>

#include "checker/collective.hpp"

namespace checker_test {

class ThreadRanks {
public:
  // Runs `check` on `ranks` threads, each as one rank of a distributed run, and returns
  // what each returned, in rank order.
  template <class Result>
  static std::vector<Result> run(int ranks, const std::function<Result()>& check) {
    ThreadRanks board(ranks);
    std::vector<Result> results(static_cast<std::size_t>(ranks));
    std::vector<std::thread> threads;
    for (int r = 0; r < ranks; ++r)
      threads.emplace_back([&, r] {
        Rank rank(board, r);
        checker::set_distributed(&rank);
        results[static_cast<std::size_t>(r)] = check();
        checker::set_distributed(nullptr);
      });
    for (auto& t : threads)
      t.join();
    return results;
  }

private:
  explicit ThreadRanks(int ranks)
      : size_(ranks), sync_(ranks), cells_(static_cast<std::size_t>(ranks * ranks)),
        values_(static_cast<std::size_t>(ranks)) {}

  class Rank : public checker::Collective {
  public:
    Rank(ThreadRanks& board, int rank) : b_(board), rank_(rank) {}
    int rank() const override { return rank_; }
    int size() const override { return b_.size_; }
    std::vector<std::uint8_t> all_to_all(const std::vector<std::uint8_t>& data,
                                         const std::vector<std::uint64_t>& offsets) override {
      for (int d = 0; d < b_.size_; ++d)
        cell(rank_, d).assign(data.begin() + static_cast<std::ptrdiff_t>(offsets[d]),
                              data.begin() + static_cast<std::ptrdiff_t>(offsets[d + 1]));
      b_.sync_.arrive_and_wait();
      std::vector<std::uint8_t> out;
      for (int s = 0; s < b_.size_; ++s)
        out.insert(out.end(), cell(s, rank_).begin(), cell(s, rank_).end());
      b_.sync_.arrive_and_wait();
      return out;
    }
    std::vector<std::uint8_t> all_gather(const std::vector<std::uint8_t>& mine,
                                         std::vector<std::uint64_t>& sizes) override {
      cell(rank_, 0) = mine;
      b_.sync_.arrive_and_wait();
      std::vector<std::uint8_t> out;
      sizes.clear();
      for (int s = 0; s < b_.size_; ++s) {
        out.insert(out.end(), cell(s, 0).begin(), cell(s, 0).end());
        sizes.push_back(cell(s, 0).size());
      }
      b_.sync_.arrive_and_wait();
      return out;
    }
    std::uint64_t sum(std::uint64_t v) override {
      return reduce(v, [](std::uint64_t a, std::uint64_t b) { return a + b; });
    }
    std::uint64_t min(std::uint64_t v) override {
      return reduce(v, [](std::uint64_t a, std::uint64_t b) { return std::min(a, b); });
    }
    std::uint64_t max(std::uint64_t v) override {
      return reduce(v, [](std::uint64_t a, std::uint64_t b) { return std::max(a, b); });
    }

  private:
    std::vector<std::uint8_t>& cell(int from, int to) {
      return b_.cells_[static_cast<std::size_t>(from * b_.size_ + to)];
    }
    template <class Op> std::uint64_t reduce(std::uint64_t v, Op op) {
      b_.values_[static_cast<std::size_t>(rank_)] = v;
      b_.sync_.arrive_and_wait();
      std::uint64_t out = b_.values_[0];
      for (int s = 1; s < b_.size_; ++s)
        out = op(out, b_.values_[static_cast<std::size_t>(s)]);
      b_.sync_.arrive_and_wait();
      return out;
    }
    ThreadRanks& b_;
    int rank_;
  };

  int size_;
  std::barrier<> sync_;
  std::vector<std::vector<std::uint8_t>> cells_; // [from * size + to]
  std::vector<std::uint64_t> values_;
};

} // namespace checker_test
