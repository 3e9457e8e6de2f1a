package org.ktcs.kernel.scheduling

import java.util.TreeSet

/**
 * The requests that deadlock avoidance holds back ([DefaultScheduler]), oldest first, each with when it was first
 * refused and why; a retry takes them all out ([takeAll]) and holds back again those still refused.
 */
internal class HeldBackRequests {
    private val requests = TreeSet(compareBy(Request::seq))
    private val since = HashMap<Long, Long>()
    private val reasons = HashMap<Long, GrantWait>()

    /** Per request the park test refused, how many releases there had been: only a release can make it safe. */
    val parkRefusedAt = HashMap<Long, Long>()

    /** The requests held back now, oldest first. */
    val all: Collection<Request> get() = requests

    fun isEmpty(): Boolean = requests.isEmpty()

    operator fun contains(request: Request): Boolean = request in requests

    /** For how long [request] has been held back since its first refusal (kernel clock millis); 0 if it is not. */
    fun heldFor(request: Request, now: Long): Long = now - (since[request.seq] ?: now)

    /** Why [request] was refused last, if it was and has not been granted since. */
    fun reason(request: Request): GrantWait? = reasons[request.seq]

    /** Holds [request] back for [why]; returns for how long it has been held back since its first refusal. */
    fun holdBack(request: Request, why: GrantWait, now: Long): Long {
        reasons[request.seq] = why
        requests += request
        since.putIfAbsent(request.seq, now)
        return heldFor(request, now)
    }

    /** For how long each client's request held back now has been (kernel clock millis), by client name. */
    fun heldFor(now: Long): Map<String, Long> = requests.associate { it.client.name to heldFor(it, now) }

    fun granted(request: Request) {
        since.remove(request.seq)
        parkRefusedAt.remove(request.seq)
        reasons.remove(request.seq)
    }

    /** Takes every request out for a retry; [forgetSettled] afterwards drops what is kept of those not held again. */
    fun takeAll(): List<Request> = requests.toList().also { requests.clear() }

    fun forgetSettled() {
        if (since.size <= requests.size && parkRefusedAt.size <= requests.size && reasons.size <= requests.size) return
        val held = requests.mapTo(HashSet()) { it.seq }
        since.keys.retainAll(held)
        parkRefusedAt.keys.retainAll(held)
        reasons.keys.retainAll(held)
    }

    fun clear() {
        requests.clear()
        since.clear()
        parkRefusedAt.clear()
        reasons.clear()
    }
}
