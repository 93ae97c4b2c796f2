// SPDX-License-Identifier: Apache-2.0
// The options the patch method and the methods built on it (fill) share: the patch sizes
// and EM schedule, k-coherence and the vote, declared once, and the check of their lists.
#pragma once

#include <string>
#include <vector>

#include <texsyn/options.h>
#include <texsyn/patch.h>

namespace texsyn::detail {

/// "patch" and "iterations", both "auto" by default (the method chooses them from the
/// sample: `auto_patch` and `auto_iterations` say how). T has std::vector<int> members
/// patch and iterations.
template <class T>
void add_patch_schedule(
    OptionTable<T>& t, int max_levels, const char* auto_patch, const char* auto_iterations)
{
    t.odd_integers("patch", &T::patch, 3, 33, 4,
        (std::string("patch sizes (odd), largest first: each level optimizes with each in turn, "
                     "the finest with the last only; auto = ")
            + auto_patch)
            .c_str(),
        "auto");
    t.integers("iterations", &T::iterations, 1, 50, max_levels,
        (std::string("EM iterations (search, then vote) per patch size, per level, finest "
                     "first (one value = every level; coarser levels missing from the list "
                     "repeat the last); auto = ")
            + auto_iterations)
            .c_str(),
        "auto");
}

/// "coherence" and "vote". T has members int coherence and PatchVote vote.
template <class T>
void add_patch_terms(OptionTable<T>& t)
{
    t.integer("coherence", &T::coherence, 1, 8,
        "k of k-coherence: each propagated candidate also brings its k-1 most similar "
        "sample patches; 1 = PatchMatch's propagation alone");
    t.choice("vote", &T::vote, { { "robust", PatchVote::Robust }, { "mean", PatchVote::Mean } },
        "how overlapping patches are averaged: robust (each weighted by how well it "
        "matches, Kwatra et al.'s IRLS weights; sharper) or mean");
}

/// The rules between the schedule's options: patch sizes largest first, and (levels > 0)
/// no more iteration values than levels. False with a message naming the option.
bool check_patch_schedule(const std::vector<int>& patch, const std::vector<int>& iterations,
    int levels, std::string& error);

} // namespace texsyn::detail
