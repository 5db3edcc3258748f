// SPDX-License-Identifier: MIT
// The step loop allocates nothing once warm: every scheme keeps its stages, the force field its
// lists and buffers. Counted by replacing the global operator new in this test program.
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>

#include <gtest/gtest.h>

#include "many_body_fixture.hpp"

namespace {
std::atomic<bool> counting{false};
std::atomic<long> allocations{0};
}  // namespace

// The replacements pair malloc with free on purpose; g++ cannot see that they match.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void* operator new(std::size_t size) {
  if (counting.load(std::memory_order_relaxed)) allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
// Every unaligned form is replaced, so whatever the library calls (the nothrow form backs
// std::stable_sort's buffer) pairs with the free below; a sanitizer flags any mix otherwise.
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  if (counting.load(std::memory_order_relaxed)) allocations.fetch_add(1, std::memory_order_relaxed);
  return std::malloc(size == 0 ? 1 : size);
}
void* operator new[](std::size_t size) { return operator new(size); }
void* operator new[](std::size_t size, const std::nothrow_t& tag) noexcept {
  return operator new(size, tag);
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
#pragma GCC diagnostic pop

namespace {

/// Allocations counted in steps without a list build and in steps with one.
struct Counts {
  long plain = 0;
  long rebuilding = 0;
  int rebuild_steps = 0;
};

Counts count_allocations(dem::SimulationSetup setup, int warm, int steps) {
  setup.neighbors.sort_every = 0;
  dem::Simulation sim(setup);
  for (int n = 0; n < warm; ++n) sim.step();
  Counts c;
  for (int n = 0; n < steps; ++n) {
    const std::uint64_t builds = sim.force_field().list_builds();
    allocations = 0;
    counting = true;
    sim.step();
    counting = false;
    if (sim.force_field().list_builds() == builds) {
      c.plain += allocations.load();
    } else {
      c.rebuilding += allocations.load();
      ++c.rebuild_steps;
    }
  }
  return c;
}

TEST(StepLoop, AllocatesNothingBetweenListBuilds) {
  for (const dem::SchemeId scheme : {dem::SchemeId::velocity_verlet, dem::SchemeId::leapfrog,
                                     dem::SchemeId::rk4, dem::SchemeId::abm, dem::SchemeId::bd2}) {
    dem::SimulationSetup setup =
        test_support::settling_box(4, test_support::full_or_sanitized<std::size_t>(300, 100));
    setup.scheme = scheme;
    const Counts c = count_allocations(setup, 200, test_support::full_or_sanitized(800, 300));
    EXPECT_EQ(c.plain, 0) << dem::scheme_info(scheme).keyword;
    EXPECT_GT(c.rebuild_steps, 0) << dem::scheme_info(scheme).keyword;
  }
}

TEST(StepLoop, ListBuildsReuseTheirStorageOnceWarm) {
  // A periodic granular gas keeps its list size: after warm-up, rebuilds find the capacity they
  // need (the list keeps an eighth in hand when it grows).
  dem::SimulationSetup setup =
      test_support::settling_box(9, test_support::full_or_sanitized<std::size_t>(1000, 343));
  setup.walls.clear();
  setup.fields.gravity.setZero();
  const double side = std::round(std::cbrt(static_cast<double>(setup.particles.size())));  // lattice rows
  setup.box.hi = dem::Vec3::Constant(side * 2.1e-3 * 1.3);
  setup.box.periodic = {true, true, true};
  const Counts c = count_allocations(setup, 2000, 2000);
  EXPECT_GT(c.rebuild_steps, 3);
  EXPECT_EQ(c.rebuilding + c.plain, 0);
}

}  // namespace
