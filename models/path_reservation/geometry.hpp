#pragma once
// The plane of seed 004, discretised: a grid of square cells, at most 64, so that an
// area (a zone, a disk) is a 64-bit set of cells. A robot covers one cell; a chunk
// (Definition 1) is a straight run of cells, horizontal, vertical or diagonal; its zone
// (Definition 3, §5.1) is the cells the robot covers on it: Pre(Zone) the first cell
// (where it waits before), Post(Zone) the last (where it waits after), Mot(Zone) every
// cell of the run. The positioning and motion errors of Definition 2 are taken as zero,
// so no margin is added (models/path_reservation/README.md, "Zones").

#include <cstdint>
#include <string>
#include <vector>

namespace path_reservation {

using CellSet = std::uint64_t;

struct Cell {
  int x = 0, y = 0;
  bool operator==(const Cell&) const = default;
};

// Definition 4 says a zone lies within Cir(pos, C/2), "a radius equal at most to half the
// transmission range": a closed disk. Read as an open disk, two robots that can reach a
// common cell are always closer than C (README, "Ranges", finding P3).
enum class DiskEdge { closed, open };

struct Zone {
  CellSet pre = 0, motion = 0, post = 0;
  CellSet all() const { return pre | motion | post; }
};

class Plane {
public:
  Plane(int width, int height); // throws std::invalid_argument beyond 64 cells

  int width() const { return width_; }
  int height() const { return height_; }
  int cells() const { return width_ * height_; }
  bool contains(Cell c) const { return c.x >= 0 && c.y >= 0 && c.x < width_ && c.y < height_; }
  int index(Cell c) const { return c.y * width_ + c.x; }
  Cell cell(int index) const { return {index % width_, index / width_}; }
  CellSet bit(Cell c) const { return CellSet{1} << index(c); }

  // The cells of the chunk from `from` to `to`, in the order the robot covers them;
  // throws std::invalid_argument unless the run is straight (|dx| = |dy| or one is 0).
  std::vector<Cell> chunk_cells(Cell from, Cell to) const;
  Zone zone(Cell from, Cell to) const;
  // Cir(centre, r): the cells whose centres are at distance <= r from centre's (< r when
  // open). Definition 4 has r = C/2, so the argument is (2r)^2 = C^2, kept whole.
  CellSet disk(Cell centre, int squared_radius_times_4, DiskEdge edge = DiskEdge::closed) const;
  // The least squared distance from `from` to a cell of `area` (the sorting criterion).
  int squared_distance(Cell from, CellSet area) const;

private:
  int width_, height_;
};

inline int squared_distance(Cell a, Cell b) {
  return (a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y);
}

std::string to_string(Cell c); // "(2,1)"

} // namespace path_reservation
