package org.ktcs.kernel.dispatching

/**
 * The best of [candidates] by [ranking] that [assess] accepts (returning it routed), routing as few as possible:
 * candidates are tried in the order [CandidateRanking.beforeRouting] gives them, one group of equally ranked ones at a
 * time, and the search stops at the first group with an accepted candidate. With keys that need no route (the
 * default `BY_DEADLINE`, `BY_AGE`, …) every group holds one candidate, so the first acceptable one wins.
 */
internal fun bestCandidate(
    candidates: List<Candidate>,
    ranking: CandidateRanking,
    assess: (Candidate) -> Candidate?,
    lowerBound: ((Candidate) -> Long?)? = null,
): Candidate? {
    if (candidates.isEmpty()) return null
    val acceptedIn = { group: List<Candidate> -> acceptedIn(group, ranking, assess, lowerBound) }
    // Most searches end with the first group: find it without sorting a vehicle's candidates among thousands of orders.
    val best = candidates.minWith(ranking.beforeRouting)
    val (first, rest) = candidates.partition { ranking.beforeRouting.compare(it, best) == 0 }
    val accepted = acceptedIn(first)
    if (accepted.isNotEmpty()) return accepted.minWith(ranking.full)
    val sorted = rest.sortedWith(ranking.beforeRouting)
    var start = 0
    while (start < sorted.size) {
        val end = groupEnd(sorted, start, ranking.beforeRouting)
        val accepted = acceptedIn(sorted.subList(start, end))
        if (accepted.isNotEmpty()) return accepted.minWith(ranking.full)
        start = end
    }
    return null
}

/**
 * The accepted candidates of one group that may be the best. With a [lowerBound] of the group's first route-cost key
 * (`null`: none known), candidates are routed cheapest bound first, and those whose bound exceeds the costs of one
 * already accepted are not routed at all: they cannot rank before it.
 */
private fun acceptedIn(
    group: List<Candidate>,
    ranking: CandidateRanking,
    assess: (Candidate) -> Candidate?,
    lowerBound: ((Candidate) -> Long?)?,
): List<Candidate> {
    val key = ranking.routeKey
    if (key == null || lowerBound == null || group.size < 2) return group.mapNotNull(assess)
    val accepted = ArrayList<Candidate>()
    var bound = Long.MAX_VALUE
    for ((candidate, lower) in group.map { it to lowerBound(it) }.sortedBy { it.second ?: Long.MAX_VALUE }) {
        if (lower != null && lower > bound) continue
        val routed = assess(candidate) ?: continue
        accepted += routed
        val costs = if (key == CandidatePriority.BY_INITIAL_ROUTING_COSTS) routed.initialCosts else routed.completeCosts
        bound = minOf(bound, costs)
    }
    return accepted
}

private fun groupEnd(sorted: List<Candidate>, start: Int, comparator: Comparator<Candidate>): Int {
    var end = start + 1
    while (end < sorted.size && comparator.compare(sorted[start], sorted[end]) == 0) end++
    return end
}
