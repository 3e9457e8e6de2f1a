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

    /** When [request] was first refused (kernel clock millis), if it was and has not been granted since. */
    fun since(request: Request): Long? = since[request.seq]

    /** Why [request] was refused last, if it was and has not been granted since. */
    fun reason(request: Request): GrantWait? = reasons[request.seq]

    fun holdBack(request: Request, why: GrantWait, now: Long) {
        reasons[request.seq] = why
        requests += request
        since.putIfAbsent(request.seq, now)
    }

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
