// SPDX-License-Identifier: MIT
#include "dem/neighbors/neighbor_list.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>


#include "dem/core/balanced_for.hpp"
#include "dem/core/parallel_for.hpp"

namespace dem {
namespace {

/// Owners per build chunk: chunks, not threads, split the work, so the list is the same for
/// any thread count.
constexpr std::uint32_t kOwnersPerChunk = 512;

/// Candidates a gather copies at a time (CellGrid pads its members by as many).
constexpr std::uint32_t kGatherBlock = 8;
static_assert(kGatherBlock <= CellGrid::kPadding);

/// Orders list entries by partner index (an owner's entries are kept in this order).
bool by_partner(PartnerCode a, PartnerCode b) noexcept { return (a & kPartnerMask) < (b & kPartnerMask); }

/// Index of the entry with partner j among `partners`, sorted by partner, or −1.
std::int64_t find_partner(std::span<const PartnerCode> partners, std::uint32_t base, std::uint32_t j) {
  const auto it = std::lower_bound(partners.begin(), partners.end(), j,
                                   [](PartnerCode e, std::uint32_t v) { return (e & kPartnerMask) < v; });
  if (it == partners.end() || (*it & kPartnerMask) != j) return -1;
  return static_cast<std::int64_t>(base) + (it - partners.begin());
}

/// The smallest box holding every centre (a point at the origin when there are none).
std::pair<Vec3, Vec3> bounding_box(std::span<const PackedSphere> spheres) noexcept {
  if (spheres.empty()) return {Vec3::Zero(), Vec3::Zero()};
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 hi = -lo;
  for (const PackedSphere& s : spheres) {
    lo = lo.cwiseMin(Vec3(s.x, s.y, s.z));
    hi = hi.cwiseMax(Vec3(s.x, s.y, s.z));
  }
  return {lo, hi};
}

}  // namespace

SizeClasses size_classes(std::span<const double> half_reach) {
  constexpr int kMaxClasses = 8;
  SizeClasses out;
  out.of.resize(half_reach.size());
  double smallest = std::numeric_limits<double>::infinity();
  for (const double h : half_reach) smallest = std::min(smallest, h);
  int used = 1;
  for (std::size_t i = 0; i < half_reach.size(); ++i) {
    int c = 0;
    double bound = 2.0 * smallest;
    while (c + 1 < kMaxClasses && half_reach[i] >= bound) {
      ++c;
      bound *= 2.0;
    }
    out.of[i] = static_cast<std::uint8_t>(c);
    used = std::max(used, c + 1);
  }
  out.max_half_reach.assign(static_cast<std::size_t>(used), 0.0);
  for (std::size_t i = 0; i < half_reach.size(); ++i) {
    double& m = out.max_half_reach[out.of[i]];
    m = std::max(m, half_reach[i]);
  }
  return out;
}

void AxisCells::fill_anew(const Request& request) {
  const auto [c, dims, edge, reach, periodic] = request;
  last_ = request;
  cell.clear();
  gap.clear();
  digit.clear();
  imaged = true;
  // More than `dims` cells either way visits nothing new (and a reach of 10¹⁰ cells would not fit
  // an int: a 1e8 m sphere beside a 1 cm one); clamped before the conversion.
  const double span = std::ceil(reach / edge);
  const int w = span < static_cast<double>(dims) ? static_cast<int>(span) : dims;
  if (periodic && 2 * w + 1 > dims) {
    // The stencil wraps onto itself: visit every cell once, at its nearest periodic offset.
    imaged = false;
    for (int t = 0; t < dims; ++t) {
      int d = (t - c) % dims;
      if (d < 0) d += dims;
      if (2 * d > dims) d -= dims;
      cell.push_back(t);
      gap.push_back(std::max(std::abs(d) - 1, 0) * edge);
      digit.push_back(1);
    }
    return;
  }
  // Here w·edge < L/2, so the image a cell is visited at is the nearest image of every sphere in
  // it that lies within reach: a pair in reach is found at its minimum image.
  for (int d = -w; d <= w; ++d) {
    int t = c + d;
    int image = 1;
    if (periodic) {
      if (t < 0) {
        t += dims;
        image = 2;
      } else if (t >= dims) {
        t -= dims;
        image = 0;
      }
    } else if (t < 0 || t >= dims) {
      continue;
    }
    cell.push_back(t);
    gap.push_back(std::max(std::abs(d) - 1, 0) * edge);
    digit.push_back(image);
  }
}

void NeighborList::build(const NeighborBuildInput& in, std::span<const std::uint32_t> new_of_old) {
  const std::span<const PackedSphere> spheres = in.spheres;
  const PeriodicBox& box = *in.box;
  const auto n = static_cast<std::uint32_t>(spheres.size());
  ++builds_;

  const auto [lo, hi] = bounding_box(spheres);

  const std::size_t classes = in.class_half_reach.size();
  class_members_.resize(classes);
  for (auto& m : class_members_) m.clear();
  for (std::uint32_t i = 0; i < n; ++i) class_members_[in.size_class[i]].push_back(i);
  double largest = 0.0;
  for (const double h : in.class_half_reach) largest = std::max(largest, h);
  const double skin = in.skin;
  slab_width_ = 2.0 * largest + skin;
  extended_history_ = in.extended_history;
  slabs_.assign(spheres, lo, hi, box, slab_width_);
  // Grid (b, c), c ≥ b, bins class b for the searches of class c (and, for c = b, of every
  // smaller class) with cells as wide as the longest such search reach, h_b + h_c + skin: every
  // search then visits at most 3 × 3 × 3 cells, whatever the size ratio. (Cells half as wide, as
  // LAMMPS bins, test fewer candidates but visit 5 × 5 × 5 cells; on the chute that cost more:
  // docs/performance.md.)
  grids_.resize(classes * classes);
  for (std::size_t b = 0; b < classes; ++b) {
    if (class_members_[b].empty()) continue;
    for (std::size_t c = b; c < classes; ++c) {
      if (c != b && class_members_[c].empty()) continue;
      const double edge = in.class_half_reach[b] + in.class_half_reach[c] + skin;
      grids_[b * classes + c].assign(spheres, class_members_[b], lo, hi, box, edge);
      // Each cell's range of slabs: a search skips the cells that hold no sphere of the owner's
      // slab or the next, whose pairs with it the owner never owns (the list is the same).
      grids_[b * classes + c].summarise(slabs_.all());
    }
  }
  const Vec3 length = box.length();
  for (std::uint32_t code = 0; code < 27; ++code) {
    const int step[3] = {static_cast<int>(code % 3) - 1, static_cast<int>(code / 3 % 3) - 1,
                         static_cast<int>(code / 9) - 1};
    for (int k = 0; k < 3; ++k) shifts_[code][k] = box.periodic[k] ? step[k] * length[k] : 0.0;
  }

  const std::uint32_t old_n = sphere_count();
  remember_interacting(std::max(in.threads, 1));

  // Units: runs of cells of each class's own grid holding about kOwnersPerChunk owners each. The owners
  // of a cell are searched one after another, so the candidates around the cell are gathered
  // once for all of them.
  const std::size_t last_units = units_.size();  // the last build's, kept in hand for this one's
  units_.clear();
  if (units_.capacity() < last_units + last_units / 8) units_.reserve(last_units + last_units / 8);
  for (std::size_t c = 0; c < classes; ++c) {
    if (class_members_[c].empty()) continue;
    const CellGrid& own = grids_[c * classes + c];
    const auto cells = static_cast<std::uint32_t>(own.cell_count());
    std::uint32_t from = 0;
    while (from < cells) {
      std::uint32_t to = from + 1;
      const std::uint32_t target = own.first(from) + kOwnersPerChunk;
      while (to < cells && own.first(to) < target) ++to;
      units_.push_back({static_cast<std::uint32_t>(c), from, to});
      from = to;
    }
  }
  const auto unit_count = static_cast<std::uint32_t>(units_.size());
  // Per-unit scratch with an eighth in hand, so that a steady scene's rebuilds reuse it.
  if (chunk_partners_.size() < unit_count) chunk_partners_.resize(unit_count + unit_count / 8);
  if (chunk_candidates_.capacity() < unit_count) {
    chunk_candidates_.reserve(unit_count + unit_count / 8);
    chunk_cells_.reserve(unit_count + unit_count / 8);
  }
  chunk_candidates_.assign(unit_count, 0);
  chunk_cells_.assign(unit_count, 0);
  // Each owner's count goes to offsets_[i + 1] (the last build's offsets are no longer read:
  // remember_interacting has taken what it needs), summed into offsets once all are known.
  offsets_.assign(n + 1, 0);
  const int threads = std::max(in.threads, 1);
  const std::uint32_t* const slab_of = slabs_.all().data();
  const std::uint8_t* const still = in.still.data();
  if (stencils_.size() < static_cast<std::size_t>(threads)) stencils_.resize(static_cast<std::size_t>(threads));
  for (Stencil& stencil : stencils_) stencil.near.resize(classes);
  // Each thread searches a run of neighbouring units (its share, then units taken from the back
  // of another's), so that its gathers and its part of the arrays stay together in its caches.
  balanced_for_threads(threads, unit_count, std::uint32_t{1}, [&](std::uint32_t thread, std::uint32_t u) {
    Stencil& stencil = stencils_[thread];
    const SearchUnit unit = units_[u];
    const std::size_t c = unit.size_class;
    const CellGrid& own = grids_[c * classes + c];
    for (Candidates& cand : stencil.near) cand.grid = nullptr;  // gathered by an earlier build
    // Counters and the partner list live in this thread's scratch while the unit is searched:
    // per-unit slots side by side share cache lines, and two threads incrementing them in the
    // inner loop made the parallel build slower than the serial one.
    std::vector<std::uint32_t>& out = stencil.partners;
    std::size_t used = 0;  // partners found so far in the unit (out holds scratch beyond)
    std::uint64_t candidates = 0;
    std::uint64_t cells = 0;
    const std::uint32_t* const member = own.members().data();
    for (std::uint32_t m = own.first(unit.from); m < own.first(unit.to); ++m) {
      const std::uint32_t i = member[m];
      const PackedSphere& si = spheres[i];
      const std::size_t first = used;
      const std::uint32_t slab_i = slab_of[i];
      const std::uint8_t still_i = still[i] != 0 ? 0xFF : 0;  // a mask: still pairs are not listed
      for (std::size_t b = 0; b < classes; ++b) {
        if (class_members_[b].empty()) continue;
        const CellGrid& grid = grids_[b * classes + std::max(b, c)];
        const auto at = grid.coordinates(si.x, si.y, si.z);
        const std::size_t cell = grid.index(at[0], at[1], at[2]);
        Candidates& cand = stencil.near[b];
        if (cand.grid != &grid || cand.cell != cell || cand.slab != slab_i) {
          gather(in, cand, stencil.axes, grid, cell, slab_i);
        }
        candidates += cand.size();
        cells += cand.cells;
        if (used + cand.size() > out.size()) out.resize(2 * (used + cand.size()));
        if (!cand.imaged) {
          used = scan<false, false>(in, cand, si, i, still_i, skin, out.data(), used);
        } else if (cand.shifted) {
          used = scan<true, true>(in, cand, si, i, still_i, skin, out.data(), used);
        } else {
          used = scan<true, false>(in, cand, si, i, still_i, skin, out.data(), used);
        }
      }
      std::sort(out.begin() + static_cast<std::ptrdiff_t>(first), out.begin() + static_cast<std::ptrdiff_t>(used),
                by_partner);
      offsets_[i + 1] = static_cast<std::uint32_t>(used - first);
    }
    std::vector<std::uint32_t>& kept = chunk_partners_[u];
    if (kept.capacity() < used) kept.reserve(used + used / 8);
    kept.assign(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(used));
    chunk_candidates_[u] = candidates;
    chunk_cells_[u] = cells;
  });

  candidates_ = 0;
  for (const std::uint64_t c : chunk_candidates_) candidates_ += c;
  cells_visited_ = 0;
  for (const std::uint64_t c : chunk_cells_) cells_visited_ += c;
  for (std::uint32_t i = 0; i < n; ++i) offsets_[i + 1] += offsets_[i];
  reserve_entries(offsets_[n]);
  // Each unit's partners, owner after owner in the unit's order, to their owners' entries.
  parallel_for(threads, unit_count, [&](std::int64_t u) {
    const SearchUnit unit = units_[static_cast<std::size_t>(u)];
    const CellGrid& own = grids_[unit.size_class * classes + unit.size_class];
    const std::uint32_t* part = chunk_partners_[static_cast<std::size_t>(u)].data();
    for (std::uint32_t m = own.first(unit.from); m < own.first(unit.to); ++m) {
      const std::uint32_t i = own.members()[m];
      const std::uint32_t count = offsets_[i + 1] - offsets_[i];
      std::copy(part, part + count, partners_.begin() + offsets_[i]);
      part += count;
    }
  });
  if (old_n != n) carried_.clear();
  finish_layout(new_of_old, threads);
}

void NeighborList::gather(const NeighborBuildInput& in, Candidates& out, AxisCells (&axes)[3], const CellGrid& grid, std::size_t cell,
                          std::uint32_t slab) const {
  out.grid = &grid;
  out.cell = cell;
  out.slab = slab;
  const std::uint32_t next_slab = slabs_.next(slab);
  // The stencil for the farthest reach the grid serves: a superset of every owner's own (each
  // owner's distance test decides), so the gathered set does not depend on the owner.
  const double reach = grid.reach();
  const double reach2 = reach * reach;
  const auto at = grid.coordinates_of(cell);
  for (int k = 0; k < 3; ++k) axes[k].fill(at[k], grid.dims()[k], grid.edge()[k], reach, in.box->periodic[k]);
  const AxisCells& ax = axes[0];
  const AxisCells& ay = axes[1];
  const AxisCells& az = axes[2];
  out.imaged = ax.imaged && ay.imaged && az.imaged;
  out.shifted = false;
  out.cells = 0;
  std::size_t count = 0;
  const std::uint32_t* const member = grid.members().data();
  // Copies the members [from, to) (cells side by side along x) with their shift code, eight at a
  // time: most runs then take one pass of a loop whose trip the processor predicts. The grid pads
  // its members and the tags keep eight in hand, so the copy may run past both ends.
  const auto copy = [&](std::uint32_t from, std::uint32_t to, std::uint32_t code) {
    const std::uint32_t n = to - from;
    if (count + n + kGatherBlock > out.tag.size()) out.tag.resize(2 * (count + n + kGatherBlock));
    std::uint32_t* const tag = out.tag.data() + count;
    const std::uint32_t shifted = code << kPartnerBits;
    for (std::uint32_t m = 0; m < n; m += kGatherBlock) {
      for (std::uint32_t q = 0; q < kGatherBlock; ++q) tag[m + q] = member[from + m + q] | shifted;
    }
    count += n;
  };
  for (std::size_t kz = 0; kz < az.cell.size(); ++kz) {
    const double gz = az.gap[kz] * az.gap[kz];
    for (std::size_t ky = 0; ky < ay.cell.size(); ++ky) {
      const double gyz = gz + ay.gap[ky] * ay.gap[ky];
      if (gyz > reach2) continue;
      const auto yz_code = static_cast<std::uint32_t>(3 * ay.digit[ky] + 9 * az.digit[kz]);
      // Cells adjacent along x are adjacent in the grid's member arrays: each run of them with
      // one image is copied as one stretch.
      std::size_t run_last = 0;
      std::uint32_t run_from = 0;
      std::uint32_t run_to = 0;
      std::uint32_t run_code = kNoShift;
      for (std::size_t kx = 0; kx < ax.cell.size(); ++kx) {
        if (gyz + ax.gap[kx] * ax.gap[kx] > reach2) continue;
        const std::size_t c = grid.index(ax.cell[kx], ay.cell[ky], az.cell[kz]);
        // A cell holding no sphere of the owners' slab or the next holds no pair they own.
        if (!grid.may_hold(c, slab, next_slab)) continue;  // ends the run
        ++out.cells;
        // Where the stencil wraps onto itself, the image is found pair by pair (no shift here).
        const std::uint32_t code = out.imaged ? yz_code + static_cast<std::uint32_t>(ax.digit[kx]) : kNoShift;
        out.shifted = out.shifted || code != kNoShift;
        if (run_to > run_from && c == run_last + 1 && code == run_code) {
          run_to = grid.first(c + 1);
        } else {
          if (run_to > run_from) copy(run_from, run_to, run_code);
          run_from = grid.first(c);
          run_to = grid.first(c + 1);
          run_code = code;
        }
        run_last = c;
      }
      if (run_to > run_from) copy(run_from, run_to, run_code);
    }
  }
  out.count = count;
}

template <bool Imaged, bool Shifted>
std::size_t NeighborList::scan(const NeighborBuildInput& in, const Candidates& cand, const PackedSphere& si, std::uint32_t i, std::uint8_t still_i,
                               double skin, std::uint32_t* out, std::size_t used) const noexcept {
  const std::uint32_t slab_i = cand.slab;
  const std::uint32_t next_slab = slabs_.next(slab_i);
  const std::size_t count = cand.size();
  const std::uint32_t* const tag = cand.tag.data();
  const std::uint32_t* const slab_of = slabs_.all().data();
  const std::uint8_t* const still = in.still.data();
  const PackedSphere* const spheres = in.spheres.data();
  const Vec3 length = Imaged ? Vec3::Zero() : in.box->length();
  const Vec3 half_length = 0.5 * length;
  // Branch-free: every candidate is written at the end of the scratch, and the count advances
  // only for a pair this owner lists (candidates pass or fail unpredictably; a mispredicted
  // branch per candidate cost more than the test).
  for (std::size_t m = 0; m < count; ++m) {
    const std::uint32_t j = tag[m] & kPartnerMask;
    std::uint32_t code = tag[m] >> kPartnerBits;
    const PackedSphere& sj = spheres[j];
    double d[3];
    if constexpr (Shifted) {
      // The owner's centre moved by the shift of the partner's cell, so the partner's wrapped
      // centre needs none.
      const Vec3& shift = shifts_[code];
      d[0] = (si.x + shift[0]) - sj.x;
      d[1] = (si.y + shift[1]) - sj.y;
      d[2] = (si.z + shift[2]) - sj.z;
    } else {
      d[0] = si.x - sj.x;
      d[1] = si.y - sj.y;
      d[2] = si.z - sj.z;
    }
    if constexpr (!Imaged) {
      // A box shorter than two reaches: the nearest image, sphere by sphere (centres are wrapped
      // at the build, so it is at most one box length away).
      int digit[3] = {1, 1, 1};
      for (int k = 0; k < 3; ++k) {
        if (!in.box->periodic[k]) continue;
        if (d[k] > half_length[k]) {
          d[k] -= length[k];
          digit[k] = 0;
        } else if (d[k] < -half_length[k]) {
          d[k] += length[k];
          digit[k] = 2;
        }
      }
      code = static_cast<std::uint32_t>(digit[0] + 3 * digit[1] + 9 * digit[2]);
    }
    const double cut = si.half_reach + sj.half_reach + skin;
    const std::uint32_t sj_slab = slab_of[j];
    // i owns (i, j): same slab and the lower index, or j in the slab after i's.
    const bool owned = ((sj_slab == slab_i) & (i < j)) | (sj_slab == next_slab);
    const bool moving = (still[j] & still_i) == 0;
    const bool near = d[0] * d[0] + d[1] * d[1] + d[2] * d[2] < cut * cut;
    out[used] = j | (code << kPartnerBits);
    used += static_cast<std::size_t>(owned & moving & near);
  }
  return used;
}

void NeighborList::reserve_entries(std::size_t total) {
  // Keep an eighth in hand when the list grows, so that rebuilds of a steady scene reuse it.
  if (partners_.capacity() < total) {
    partners_.reserve(total + total / 8);
    contact_.reserve(total + total / 8);
    owner_step_.reserve(total + total / 8);
  }
  partners_.resize(total);
  contact_.assign(total, kNoContact);
}

void NeighborList::finish_layout(std::span<const std::uint32_t> new_of_old, int threads) {
  const std::uint32_t n = sphere_count();
  const std::size_t total = partners_.size();
  periodic_ = false;
  shifted_.assign(n, 0);
  owner_step_.resize(total);
  parallel_for(threads, n, [&](std::uint32_t i) {
    for (std::uint32_t k = offsets_[i]; k < offsets_[i + 1]; ++k) {
      if ((partners_[k] >> kPartnerBits) != kNoShift) shifted_[i] = 1;
    }
  });
  for (std::uint32_t i = 0; i < n; ++i) periodic_ = periodic_ || shifted_[i] != 0;
  // Each slab's owners as runs of consecutive indices alike in `shifted`, at most 256 owners
  // long: their entries are consecutive too, the pair loop tests them in one loop per run, and
  // an entry's owner is the run's first plus the entry's step (one byte). Slab by slab, in
  // parallel: count, then write (so that a steady scene's rebuilds reuse the storage).
  const std::uint32_t slab_count = slabs_.count();
  slab_runs_.assign(slab_count + 1, 0);
  slab_base_.assign(slab_count + 1, 0);
  parallel_for(threads, slab_count, [&](std::uint32_t sl) {
    slab_runs_[sl + 1] = lay_out_runs(sl, nullptr);
    // Slab s's pairs can hold at most as many contacts as it has entries: its slots start where
    // the entries of the slabs before it end.
    std::uint32_t entries = 0;
    for (const std::uint32_t i : slabs_.members(sl)) entries += offsets_[i + 1] - offsets_[i];
    slab_base_[sl + 1] = entries;
  });
  for (std::uint32_t sl = 0; sl < slab_count; ++sl) {
    slab_runs_[sl + 1] += slab_runs_[sl];
    slab_base_[sl + 1] += slab_base_[sl];
  }
  const std::uint32_t run_count = slab_runs_[slab_count];
  if (runs_.capacity() < run_count) runs_.reserve(run_count + run_count / 8);
  runs_.resize(run_count);
  parallel_for(threads, slab_count, [&](std::uint32_t sl) { lay_out_runs(sl, runs_.data() + slab_runs_[sl]); });
  for (int b = 0; b < 2; ++b) {
    if (slips_[b].capacity() < total) slips_[b].reserve(partners_.capacity());
    slips_[b].resize(total);
    if (extended_history_) {
      if (extended_[b].capacity() < total) extended_[b].reserve(partners_.capacity());
      extended_[b].resize(total);
    } else {
      extended_[b].clear();
    }
  }
  carry_history(new_of_old, threads);
  lay_out_carried(threads);
}

std::uint32_t NeighborList::lay_out_runs(std::uint32_t slab, EntryRun* out) noexcept {
  std::uint32_t count = 0;
  bool open = false;
  std::uint32_t end = 0;  // of the open run
  std::uint32_t first = 0;
  std::uint8_t shifted = 0;
  for (const std::uint32_t i : slabs_.members(slab)) {
    if (offsets_[i] == offsets_[i + 1]) continue;  // no entries
    // Entries that follow the run's own (only owners without entries lie between) extend it.
    if (open && offsets_[i] == end && shifted_[i] == shifted && i - first <= kMaxOwnerStep) {
      if (out != nullptr) out[count - 1].end = offsets_[i + 1];
    } else {
      if (out != nullptr) out[count] = {offsets_[i], offsets_[i + 1], i, shifted_[i]};
      ++count;
      open = true;
      first = i;
      shifted = shifted_[i];
    }
    if (out != nullptr) {
      for (std::uint32_t k = offsets_[i]; k < offsets_[i + 1]; ++k) owner_step_[k] = static_cast<std::uint8_t>(i - first);
    }
    end = offsets_[i + 1];
  }
  return count;
}

void NeighborList::permute(std::span<const PackedSphere> spheres, const PeriodicBox& box,
                           std::span<const std::uint32_t> new_of_old, int threads) {
  const std::uint32_t n = sphere_count();
  if (spheres.size() != n || new_of_old.size() != n) {
    throw std::invalid_argument("NeighborList::permute: the spheres or the map do not match the list");
  }
  remember_interacting(threads);
  // The slabs of the same centres in the new numbering (the partition depends on positions only).
  const auto [lo, hi] = bounding_box(spheres);
  slabs_.assign(spheres, lo, hi, box, slab_width_);
  // Each pair under its owner in the new numbering: when the other sphere owns it now, the pair
  // is seen from the other side, so its periodic shift is mirrored (every digit d → 2 − d).
  // Two passes over a copy of the old entries (held only here): count per owner, then place.
  const std::vector<PartnerCode> old_partners = partners_;
  const std::vector<std::uint32_t> old_offsets = offsets_;
  const auto renumbered = [&](std::uint32_t a, std::uint32_t k) {
    std::uint32_t owner = new_of_old[a];
    std::uint32_t partner = new_of_old[old_partners[k] & kPartnerMask];
    std::uint32_t code = old_partners[k] >> kPartnerBits;
    if (!slabs_.owns(owner, partner)) {
      std::swap(owner, partner);
      code = 26 - code;
    }
    return std::pair<std::uint32_t, PartnerCode>{owner, partner | (code << kPartnerBits)};
  };
  std::fill(offsets_.begin(), offsets_.end(), 0U);
  for (std::uint32_t a = 0; a < n; ++a) {
    for (std::uint32_t k = old_offsets[a]; k < old_offsets[a + 1]; ++k) ++offsets_[renumbered(a, k).first + 1];
  }
  for (std::uint32_t i = 0; i < n; ++i) offsets_[i + 1] += offsets_[i];
  reserve_entries(offsets_[n]);
  std::vector<std::uint32_t> next_free(offsets_.begin(), offsets_.end() - 1);
  for (std::uint32_t a = 0; a < n; ++a) {
    for (std::uint32_t k = old_offsets[a]; k < old_offsets[a + 1]; ++k) {
      const auto [owner, entry] = renumbered(a, k);
      partners_[next_free[owner]++] = entry;
    }
  }
  for (std::uint32_t i = 0; i < n; ++i) {
    std::sort(partners_.begin() + offsets_[i], partners_.begin() + offsets_[i + 1],
              by_partner);
  }
  finish_layout(new_of_old, threads);
}

void NeighborList::remember_interacting(int threads) {
  const std::uint32_t n = sphere_count();
  const std::span<const Vec3> slip = slips();
  const std::span<const ExtendedHistory> ext = extended();
  // In blocks of owners, in parallel: count the interacting pairs, then write them in owner
  // order (the order does not depend on the thread count).
  const std::uint32_t blocks = (n + kOwnersPerChunk - 1) / kOwnersPerChunk;
  block_start_.assign(blocks + 1, 0);
  const auto each_active = [&](std::uint32_t block, auto&& take) {
    const std::uint32_t end = std::min(n, (block + 1) * kOwnersPerChunk);
    for (std::uint32_t a = block * kOwnersPerChunk; a < end; ++a) {
      for (std::uint32_t k = offsets_[a]; k < offsets_[a + 1]; ++k) {
        if (contact_[k] != kNoContact) take(a, k);
      }
    }
  };
  parallel_for(threads, blocks, [&](std::uint32_t block) {
    std::uint32_t count = 0;
    each_active(block, [&](std::uint32_t, std::uint32_t) { ++count; });
    block_start_[block + 1] = count;
  });
  for (std::uint32_t b = 0; b < blocks; ++b) block_start_[b + 1] += block_start_[b];
  const std::uint32_t total = block_start_[blocks];
  if (carried_.capacity() < total) carried_.reserve(total + total / 8);
  carried_.resize(total);
  if (!ext.empty() && carried_extended_.capacity() < total) carried_extended_.reserve(total + total / 8);
  carried_extended_.resize(ext.empty() ? 0 : total);
  parallel_for(threads, blocks, [&](std::uint32_t block) {
    std::uint32_t at = block_start_[block];
    each_active(block, [&](std::uint32_t a, std::uint32_t k) {
      const std::uint32_t c = contact_[k];
      carried_[at] = {a, partners_[k] & kPartnerMask, slip[c]};
      if (!ext.empty()) carried_extended_[at] = ext[c];
      ++at;
    });
  });
}

void NeighborList::carry_history(std::span<const std::uint32_t> new_of_old, int threads) {
  const bool mapped = !new_of_old.empty();
  const auto count = static_cast<std::int64_t>(carried_.size());
  parallel_for(threads, count, [&](std::int64_t c) {
    Carried& old = carried_[static_cast<std::size_t>(c)];
    const std::uint32_t i = mapped ? new_of_old[old.owner] : old.owner;
    const std::uint32_t j = mapped ? new_of_old[old.partner] : old.partner;
    bool i_owns = true;
    const std::int64_t e = find(i, j, i_owns);
    if (e < 0) return;  // no longer listed: beyond reach, so its history would reset anyway
    contact_[static_cast<std::size_t>(e)] = static_cast<std::uint32_t>(c);
    if (!i_owns) old.slip = -old.slip;  // the slip is oriented owner → partner
  });
}

void NeighborList::lay_out_carried(int threads) {
  std::vector<Vec3>& slip = slips_[current_];
  std::vector<ExtendedHistory>& ext = extended_[current_];
  // Each slab fills its own range of slots.
  parallel_for(threads, slabs_.count(), [&](std::uint32_t sl) {
    std::uint32_t slot = slab_base_[sl];
    for (const std::uint32_t i : slabs_.members(sl)) {
      for (std::uint32_t k = offsets_[i]; k < offsets_[i + 1]; ++k) {
        const std::uint32_t c = contact_[k];
        if (c == kNoContact) continue;
        slip[slot] = carried_[c].slip;
        if (!ext.empty()) ext[slot] = c < carried_extended_.size() ? carried_extended_[c] : ExtendedHistory{};
        contact_[k] = slot++;
      }
    }
  });
}

void NeighborList::set_history(std::size_t k, const ContactHistory& h) {
  // Every contact (the new one included) becomes a carried pair and is laid out afresh.
  std::vector<std::uint32_t> carried_of_entry(contact_.size(), kNoContact);
  carried_.clear();
  carried_extended_.clear();
  const std::span<const Vec3> slip = slips();
  const std::span<const ExtendedHistory> ext = extended();
  for (std::size_t e = 0; e < contact_.size(); ++e) {
    if (e != k && contact_[e] == kNoContact) continue;
    carried_of_entry[e] = static_cast<std::uint32_t>(carried_.size());
    if (e == k) {
      carried_.push_back({0, 0, h.tangential_slip});
      carried_extended_.push_back(extended_of(h));
    } else {
      const std::uint32_t c = contact_[e];
      carried_.push_back({0, 0, slip[c]});
      carried_extended_.push_back(ext.empty() ? ExtendedHistory{} : ext[c]);
    }
  }
  contact_ = std::move(carried_of_entry);
  lay_out_carried(1);
}

std::int64_t NeighborList::find(std::uint32_t i, std::uint32_t j, bool& i_owns) const noexcept {
  if (i >= sphere_count() || j >= sphere_count()) return -1;
  const std::span<const PartnerCode> all = partners_;
  std::int64_t k = find_partner(all.subspan(offsets_[i], offsets_[i + 1] - offsets_[i]), offsets_[i], j);
  i_owns = true;
  if (k >= 0) return k;
  k = find_partner(all.subspan(offsets_[j], offsets_[j + 1] - offsets_[j]), offsets_[j], i);
  i_owns = false;
  return k;
}

ContactHistory NeighborList::history(std::size_t k) const noexcept {
  const std::uint32_t c = contact_[k];
  if (c == kNoContact) return {};
  return history_of(slips_[current_][c], extended_[current_].empty() ? nullptr : &extended_[current_][c]);
}

std::size_t NeighborList::bytes() const noexcept {
  std::size_t total = (offsets_.capacity() + slab_runs_.capacity() + block_start_.capacity()) * sizeof(std::uint32_t) +
                      owner_step_.capacity() + runs_.capacity() * sizeof(EntryRun) + shifted_.capacity() +
                      partners_.capacity() * sizeof(PartnerCode) + contact_.capacity() * sizeof(std::uint32_t) +
                      (slips_[0].capacity() + slips_[1].capacity()) * sizeof(Vec3) +
                      (extended_[0].capacity() + extended_[1].capacity()) * sizeof(ExtendedHistory) +
                      carried_.capacity() * sizeof(Carried) +
                      carried_extended_.capacity() * sizeof(ExtendedHistory) +
                      slab_base_.capacity() * sizeof(std::uint32_t) + slabs_.bytes();
  for (const auto& g : grids_) total += g.bytes();
  for (const auto& m : class_members_) total += m.capacity() * sizeof(std::uint32_t);
  for (const auto& c : chunk_partners_) total += c.capacity() * sizeof(std::uint32_t);
  for (const auto& s : stencils_) {
    total += s.partners.capacity() * sizeof(std::uint32_t);
    for (const Candidates& c : s.near) total += c.tag.capacity() * sizeof(PartnerCode);
  }
  total += units_.capacity() * sizeof(SearchUnit);
  return total;
}

}  // namespace dem
