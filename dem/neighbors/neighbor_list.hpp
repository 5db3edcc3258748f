// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "dem/contact/contact_history.hpp"
#include "dem/core/vector.hpp"
#include "dem/domain/periodic_box.hpp"
#include "dem/neighbors/cell_grid.hpp"
#include "dem/neighbors/packed_sphere.hpp"
#include "dem/neighbors/slab_partition.hpp"

namespace dem {

/// How the neighbour list is kept (thesis appendix B.2).
struct NeighborSettings {
  double skin = 0.0;  ///< Verlet skin [m]: the list holds pairs within h_i + h_j + skin; > 0
  /// Reorder the spheres along a Morton curve every this many list builds (0: never). Scenes of
  /// fewer than kMinSpheresToReorder spheres are never reordered.
  std::uint32_t sort_every = 8;
};

/// Scenes smaller than this fit in cache; reordering them cannot pay.
inline constexpr std::size_t kMinSpheresToReorder = 256;

/// A pair's partner as the list stores it: the partner's index in the low kPartnerBits bits, the
/// periodic shift code in the five above.
using PartnerCode = std::uint32_t;

/// Contact slot of a list entry whose pair did not interact at the last commit.
inline constexpr std::uint32_t kNoContact = 0xFFFFFFFFU;

/// The rest of a pair's history, beside the list (touched only for interacting pairs).
struct ExtendedHistory {
  Vec3 rolling_slip = Vec3::Zero();
  double max_overlap = 0.0;
  std::uint8_t attached = 0;
  Vec3 normal = Vec3::Zero();  ///< ContactHistory::normal
  double tangential_stiffness = 0.0;  ///< ContactHistory::tangential_stiffness
};

/// The extended part of a history, as the lists store it.
[[nodiscard]] inline ExtendedHistory extended_of(const ContactHistory& h) noexcept {
  return {h.rolling_slip, h.max_overlap, static_cast<std::uint8_t>(h.attached ? 1 : 0), h.normal,
          h.tangential_stiffness};
}
/// A committed history from a stored slip and its extended record (null when none is kept).
[[nodiscard]] inline ContactHistory history_of(const Vec3& slip, const ExtendedHistory* x) noexcept {
  if (x == nullptr) return {slip, Vec3::Zero(), 0.0, false, Vec3::Zero(), 0.0};
  return {slip, x->rolling_slip, x->max_overlap, x->attached != 0, x->normal, x->tangential_stiffness};
}

/// What a build reads.
struct NeighborBuildInput {
  std::span<const PackedSphere> spheres;   ///< wrapped centres and half reaches
  std::span<const std::uint8_t> still;     ///< 1: the sphere never moves (pairs of two are skipped)
  std::span<const std::uint8_t> size_class;  ///< class of each sphere (size_classes())
  std::span<const double> class_half_reach;  ///< largest half reach per class [m]
  const PeriodicBox* box;
  double skin;
  int threads;
  bool extended_history;  ///< keep ExtendedHistory (rolling slip, largest overlap, JKR neck, Mindlin k_t)
};

/// Size classes for a polydisperse population: class c holds the spheres with
/// h_min·2^c ≤ h < h_min·2^(c+1) (at most 8 classes, the last open-ended). Each class gets its
/// own cell grid so that small spheres are not binned in cells sized for the largest (thesis
/// B.1's over-reporting with polydispersity).
struct SizeClasses {
  std::vector<std::uint8_t> of;        ///< class of each sphere
  std::vector<double> max_half_reach;  ///< largest h in each class [m]
};
/// Classes of the half reaches h.
[[nodiscard]] SizeClasses size_classes(std::span<const double> half_reach);

/// The cells a search visits along one axis around a sphere's cell, each one's gap (the
/// smallest distance between the sphere's cell and that cell along the axis) [m] and the image
/// its spheres are seen at.
struct AxisCells {
  std::vector<int> cell;
  std::vector<double> gap;
  /// Shift digit of each cell's spheres along the axis: 1 as they are, 0 seen one box length
  /// up (the cell lies past the top face), 2 one box length down (past the bottom face).
  std::vector<int> digit;
  /// False when the stencil wraps onto itself (reach ≥ half the periodic length): each cell is
  /// then visited once and the nearest image must be found sphere by sphere.
  bool imaged = true;
  /// Cells within `reach` of cell `c` of a row of `dims` cells of edge `edge`.
  void fill(int c, int dims, double edge, double reach, bool periodic) {
    // Successive owners (spatially sorted) mostly sit in the same cell row: reuse the last stencil.
    const Request request{c, dims, edge, reach, periodic};
    if (!cell.empty() && request == last_) return;
    fill_anew(request);
  }

 private:
  /// The arguments of a fill.
  struct Request {
    int c = -1;
    int dims = 0;
    double edge = 0.0;
    double reach = 0.0;
    bool periodic = false;
    bool operator==(const Request&) const = default;
  };
  Request last_;  ///< the arguments of the fill the members hold
  /// fill for arguments other than the last ones.
  void fill_anew(const Request& request);
};

/// A half Verlet list in CSR form (offsets + partner codes) built from per-class cell grids, with
/// contact history beside it (each entry's contact slot points into dense history arrays that a
/// commit rewrites in list order), carried over when the list is rebuilt or the spheres are
/// reordered. Every pair within h_i + h_j + skin at the build is listed exactly
/// once, under its owner (SlabPartition::owns), with the periodic image of the partner nearest
/// the owner; partners of an owner are sorted by index.
class NeighborList {
 public:
  /// Rebuilds the list for `in`. `new_of_old` maps the spheres' indices at the previous build to
  /// the current ones (empty: unchanged); the history of every pair that interacted is carried
  /// to its new entry (its slip negated when the owner changed), or dropped when the pair is no
  /// longer listed (it is then beyond reach).
  void build(const NeighborBuildInput& in, std::span<const std::uint32_t> new_of_old = {});

  /// Renumbers the list after the spheres were reordered (`new_of_old`, as for build) without
  /// searching again: every pair keeps its entry and history under its owner in the new
  /// numbering, the slabs follow the centres `spheres` (in the new order). When the centres are
  /// those of the last build, the list is exactly what build() would make of them; otherwise it
  /// is the last build's list renumbered, valid for as long as that one was. No new build is
  /// counted.
  void permute(std::span<const PackedSphere> spheres, const PeriodicBox& box,
               std::span<const std::uint32_t> new_of_old, int threads);

  /// Number of spheres at the last build.
  [[nodiscard]] std::uint32_t sphere_count() const noexcept {
    return offsets_.empty() ? 0 : static_cast<std::uint32_t>(offsets_.size() - 1);
  }
  /// First entry of owner i; entries of i are [begin(i), begin(i + 1)).
  [[nodiscard]] std::uint32_t begin(std::uint32_t i) const noexcept { return offsets_[i]; }
  /// Number of listed pairs.
  [[nodiscard]] std::size_t size() const noexcept { return partners_.size(); }
  /// Partner and shift code of every entry (the only array the pair loop's distance test reads
  /// besides `contacts`; the history arrays are touched only for pairs in reach).
  [[nodiscard]] std::span<const PartnerCode> partners() const noexcept { return partners_; }
  /// The contact slot of every entry: where its committed history sits in the history arrays,
  /// or kNoContact when the pair did not interact at the last commit.
  [[nodiscard]] std::span<std::uint32_t> contacts() noexcept { return contact_; }
  [[nodiscard]] std::span<const std::uint32_t> contacts() const noexcept { return contact_; }
  /// True when entry k's pair interacted at the last commit.
  [[nodiscard]] bool active(std::size_t k) const noexcept { return contact_[k] != kNoContact; }
  /// Committed tangential slips by contact slot, oriented owner → partner.
  [[nodiscard]] std::span<const Vec3> slips() const noexcept { return slips_[current_]; }
  /// Committed extended history by contact slot (empty unless the build asked for it).
  [[nodiscard]] std::span<const ExtendedHistory> extended() const noexcept { return extended_[current_]; }
  /// Where a commit writes: the history arrays the next commit makes current.
  [[nodiscard]] std::span<Vec3> next_slips() noexcept { return slips_[1 - current_]; }
  [[nodiscard]] std::span<ExtendedHistory> next_extended() noexcept { return extended_[1 - current_]; }
  /// First contact slot of slab s: a commit gives the pairs of slab s that interact the slots
  /// base, base + 1, … in list order, so each slab writes its own range (any thread count) and
  /// the next evaluation reads the history of the touching pairs as one dense, ordered stream.
  [[nodiscard]] std::uint32_t slab_contact_base(std::uint32_t s) const noexcept { return slab_base_[s]; }
  /// Makes the history a commit wrote (next_slips, next_extended, the new slots in contacts())
  /// the committed one.
  void finish_commit() noexcept { current_ = 1 - current_; }
  /// Sets the committed history of entry k, oriented owner → partner (tests and tools; lays
  /// out every contact afresh, O(list)).
  void set_history(std::size_t k, const ContactHistory& h);
  /// The shift (a whole number of box lengths per axis) to subtract from the partner's wrapped
  /// centre to get its image nearest the owner, by shift code.
  [[nodiscard]] const Vec3& shift(std::uint32_t code) const noexcept { return shifts_[code]; }
  /// True when some entry has a non-zero shift.
  [[nodiscard]] bool periodic() const noexcept { return periodic_; }
  /// 1 when some entry of owner i has a non-zero shift (the spheres near a periodic face).
  [[nodiscard]] std::uint8_t shifted(std::uint32_t i) const noexcept { return shifted_[i]; }
  /// Consecutive entries whose owners are consecutive spheres of one slab, all with or all
  /// without a periodic shift (`shifted`).
  struct EntryRun {
    std::uint32_t begin, end;
    std::uint32_t first_owner;  ///< owner of entry k: first_owner + owner_steps()[k]
    std::uint8_t shifted;
  };
  /// The most a run's owners lie past its first (owner steps are one byte).
  static constexpr std::uint32_t kMaxOwnerStep = 255;
  /// The runs that cover the entries of slab s's owners, in owner order (owners without entries
  /// are left out).
  [[nodiscard]] std::span<const EntryRun> runs(std::uint32_t s) const noexcept {
    return {runs_.data() + slab_runs_[s], runs_.data() + slab_runs_[s + 1]};
  }
  /// Each entry's owner less the first owner of its run (see EntryRun).
  [[nodiscard]] std::span<const std::uint8_t> owner_steps() const noexcept { return owner_step_; }
  /// The slabs the pair loop runs over.
  [[nodiscard]] const SlabPartition& slabs() const noexcept { return slabs_; }
  /// Entry index of the pair (i, j) in either orientation and whether i is its owner, or −1.
  [[nodiscard]] std::int64_t find(std::uint32_t i, std::uint32_t j, bool& i_owns) const noexcept;
  /// The committed history of entry k, oriented owner → partner (fresh when not active).
  [[nodiscard]] ContactHistory history(std::size_t k) const noexcept;
  /// Builds so far.
  [[nodiscard]] std::uint64_t builds() const noexcept { return builds_; }
  /// Distance tests the last build made (the search's cost; compare with size()).
  [[nodiscard]] std::uint64_t last_build_candidates() const noexcept { return candidates_; }
  /// Cells the last build visited.
  [[nodiscard]] std::uint64_t last_build_cells() const noexcept { return cells_visited_; }
  /// Bytes held (list, history, grids, slabs, scratch).
  [[nodiscard]] std::size_t bytes() const noexcept;

 private:
  /// A pair that interacted at the last commit, remembered across a build.
  struct Carried {
    std::uint32_t owner;
    std::uint32_t partner;
    Vec3 slip;
  };
  /// Copies the pairs that interacted at the last commit, with their history, to carried_.
  void remember_interacting(int threads);
  /// The runs of slab `slab` (see runs()); writes them and the entries' owner steps when `out`
  /// is not null; returns how many.
  std::uint32_t lay_out_runs(std::uint32_t slab, EntryRun* out) noexcept;
  /// Sizes partners_ (contents to be written) and clears contact_ for `total` entries.
  void reserve_entries(std::size_t total);
  /// What follows the entries of every owner: shift flags, slab slot bases, history arrays, and
  /// the carried history laid out in its new slots.
  void finish_layout(std::span<const std::uint32_t> new_of_old, int threads);
  void carry_history(std::span<const std::uint32_t> new_of_old, int threads);
  /// Gives every entry whose contact_ holds an index into carried_ a slot, slab by slab in
  /// list order, and copies its history there (carry_history has already oriented it).
  void lay_out_carried(int threads);

  std::vector<std::uint32_t> offsets_;
  std::vector<PartnerCode> partners_;
  std::vector<std::uint8_t> shifted_;
  std::vector<std::uint8_t> owner_step_;  // each entry's owner less its run's first
  std::vector<EntryRun> runs_;           // per slab (slab_runs_ indexes them)
  std::vector<std::uint32_t> slab_runs_;
  std::vector<std::uint32_t> block_start_;  // scratch of remember_interacting
  std::vector<std::uint32_t> contact_;
  std::array<std::vector<Vec3>, 2> slips_;
  std::array<std::vector<ExtendedHistory>, 2> extended_;
  int current_ = 0;  // which of the two history arrays holds the committed history
  std::vector<std::uint32_t> slab_base_;
  std::array<Vec3, 27> shifts_{};
  bool periodic_ = false;
  SlabPartition slabs_;
  std::vector<CellGrid> grids_;
  std::vector<std::vector<std::uint32_t>> class_members_;
  std::uint64_t builds_ = 0;
  double slab_width_ = 0.0;         // the slabs' least width at the last build [m]
  bool extended_history_ = false;  // the last build kept ExtendedHistory
  std::uint64_t candidates_ = 0;
  std::uint64_t cells_visited_ = 0;
  std::vector<Carried> carried_;  // interacting pairs of the previous build
  std::vector<ExtendedHistory> carried_extended_;  // beside carried_, when the model keeps it
  /// A unit of the search: cells [from, to) of class c's own grid, whose members (about kChunk
  /// spheres) it lists as owners. Units, not threads, split the work.
  struct SearchUnit {
    std::uint32_t size_class;
    std::uint32_t from, to;
  };
  /// The spheres of the cells around one cell of one grid that may pair with an owner of a given
  /// slab, gathered once for all the owners in that cell as their indices tagged with their
  /// cell's shift code: each owner's distance tests then run in one loop over one short stream.
  struct Candidates {
    std::size_t cell = 0;      // the key: cell of the grid, owners' slab (valid when `grid` is set)
    std::uint32_t slab = 0;
    const CellGrid* grid = nullptr;
    bool imaged = true;        // false: the nearest image is found pair by pair
    bool shifted = false;      // some candidate is seen through a periodic face
    std::uint64_t cells = 0;   // cells gathered
    std::size_t count = 0;     // candidates gathered: tag[0, count)
    std::vector<PartnerCode> tag;  // each candidate with the shift code of its cell
    [[nodiscard]] std::size_t size() const noexcept { return count; }
  };
  /// Gathers into `out` the spheres of `grid`'s cells around `cell` that may pair with an owner of
  /// slab `slab` (its own slab or the next).
  void gather(const NeighborBuildInput& in, Candidates& out, AxisCells (&axes)[3], const CellGrid& grid, std::size_t cell, std::uint32_t slab) const;
  /// Tests owner i (centre `si`) against `cand`; appends the partners it lists (with their shift
  /// codes) at out[used...] and returns the new count.
  template <bool Imaged, bool Shifted>
  std::size_t scan(const NeighborBuildInput& in, const Candidates& cand, const PackedSphere& si, std::uint32_t i, std::uint8_t still_i,
                   double skin, std::uint32_t* out, std::size_t used) const noexcept;

  // Per-unit scratch of the build (units of cells, independent of the thread count): the
  // partners found, owner after owner in the unit's order, with their shift codes.
  std::vector<SearchUnit> units_;
  std::vector<std::vector<std::uint32_t>> chunk_partners_;
  std::vector<std::uint64_t> chunk_candidates_;
  std::vector<std::uint64_t> chunk_cells_;
  // One cache line apart: each thread rewrites its vectors' ends for every sphere it searches.
  struct alignas(64) Stencil {
    AxisCells axes[3];
    std::vector<Candidates> near;         // per size class of the partners
    std::vector<std::uint32_t> partners;  // the partners of the unit being searched
  };
  std::vector<Stencil> stencils_;  // per thread
};

}  // namespace dem
