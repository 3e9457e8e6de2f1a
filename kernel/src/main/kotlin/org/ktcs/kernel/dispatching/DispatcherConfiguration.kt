package org.ktcs.kernel.dispatching

/**
 * How [DefaultDispatcher] assigns orders and handles idle vehicles: openTCS's `defaultdispatcher.*` keys with
 * openTCS's defaults, except [parkIdleVehicles] and [rechargeIdleVehicles].
 *
 * Every priority list is applied in its order, each key breaking the ties of the ones before it; when all keys tie,
 * orders fall back to age and then name, vehicles to name, so the result never depends on iteration order.
 *
 * @property orderPriorities how orders are ranked when there are at least as many vehicles as orders, so each order
 *   in turn picks its vehicle (`defaultdispatcher.orderPriorities`).
 * @property vehiclePriorities how vehicles are ranked when there are fewer vehicles than orders, so each vehicle in
 *   turn picks its order (`defaultdispatcher.vehiclePriorities`).
 * @property vehicleCandidatePriorities how an order chooses among the vehicles that could do it
 *   (`defaultdispatcher.vehicleCandidatePriorities`).
 * @property orderCandidatePriorities how a vehicle chooses among the orders it could do
 *   (`defaultdispatcher.orderCandidatePriorities`). kTCS's default adds `BY_INITIAL_ROUTING_COSTS` after openTCS's
 *   `BY_DEADLINE`: a vehicle that becomes free takes the nearest of the orders in its [orderCandidateWindow] instead
 *   of driving empty across the plant to the oldest one.
 * @property orderCandidateWindow how many orders a vehicle chooses among (kTCS, not in openTCS): the ones ranked most
 *   urgent by [orderPriorities] among those it may take; 0 means all. It is also the fairness bound: an order that
 *   vehicles passed over this many times (they took a less urgent one) is taken before any other by the next vehicle
 *   that has it in its window and can take it, so no order waits for ever while nearer ones keep coming (only more
 *   urgent orders, e.g. with earlier deadlines, can push it out of the windows).
 * @property deadlineAtRiskPeriodMillis how long before its deadline an order counts as at risk for
 *   `DEADLINE_AT_RISK_FIRST` (`defaultdispatcher.deadlineAtRiskPeriod`).
 * @property assignRedundantOrders whether an order whose only destination is the vehicle's current point, with
 *   operation `NOP…` or `MOVE`, is assigned anyway (`defaultdispatcher.assignRedundantOrders`).
 * @property parkIdleVehicles whether idle vehicles get parking orders (`defaultdispatcher.parkIdleVehicles`).
 *   `true` unlike openTCS: an idle vehicle left standing on a road blocks the vehicles that need to pass it.
 * @property parkIdleVehiclesDelayMillis how long a vehicle must have been idle before it is sent to park
 *   (`defaultdispatcher.parkIdleVehiclesDelay`), counted from its `procStateTimestamp`.
 * @property considerParkingPositionPriorities whether park positions with a lower `tcs:parkingPositionPriority` are
 *   preferred to closer ones (`defaultdispatcher.considerParkingPositionPriorities`).
 * @property reparkVehiclesToHigherPriorityPositions whether parked vehicles move on to a free park position of
 *   higher priority; needs [considerParkingPositionPriorities]
 *   (`defaultdispatcher.reparkVehiclesToHigherPriorityPositions`).
 * @property rechargeIdleVehicles whether idle vehicles with a degraded energy level get recharge orders
 *   (`defaultdispatcher.rechargeIdleVehicles`). `true` unlike openTCS: kTCS's simulated vehicles drain energy, and
 *   without recharging a fleet ends up stuck at critical levels.
 * @property rechargeIdleVehiclesDelayMillis how long a vehicle must have been idle before it is sent to recharge
 *   (`defaultdispatcher.rechargeIdleVehiclesDelay`), counted from its `procStateTimestamp`.
 * @property keepRechargingUntilFullyCharged whether a charging vehicle stays unavailable until fully recharged
 *   instead of only until the recovery evaluator says it recovered
 *   (`defaultdispatcher.keepRechargingUntilFullyCharged`).
 */
data class DispatcherConfiguration(
    val orderPriorities: List<OrderPriority> = listOf(OrderPriority.BY_DEADLINE),
    val vehiclePriorities: List<VehiclePriority> = listOf(VehiclePriority.IDLE_FIRST, VehiclePriority.BY_ENERGY_LEVEL),
    val vehicleCandidatePriorities: List<CandidatePriority> =
        listOf(CandidatePriority.IDLE_FIRST, CandidatePriority.BY_ENERGY_LEVEL),
    val orderCandidatePriorities: List<CandidatePriority> =
        listOf(CandidatePriority.BY_DEADLINE, CandidatePriority.BY_INITIAL_ROUTING_COSTS),
    val orderCandidateWindow: Int = DEFAULT_ORDER_CANDIDATE_WINDOW,
    val deadlineAtRiskPeriodMillis: Long = 60_000,
    val assignRedundantOrders: Boolean = false,
    val parkIdleVehicles: Boolean = true,
    val parkIdleVehiclesDelayMillis: Long = 0,
    val considerParkingPositionPriorities: Boolean = false,
    val reparkVehiclesToHigherPriorityPositions: Boolean = false,
    val rechargeIdleVehicles: Boolean = true,
    val rechargeIdleVehiclesDelayMillis: Long = 0,
    val keepRechargingUntilFullyCharged: Boolean = true,
) {
    init {
        require(orderCandidateWindow >= 0) { "orderCandidateWindow must not be negative, was $orderCandidateWindow" }
        require(deadlineAtRiskPeriodMillis >= 0) {
            "deadlineAtRiskPeriodMillis must not be negative, was $deadlineAtRiskPeriodMillis"
        }
        require(parkIdleVehiclesDelayMillis >= 0) {
            "parkIdleVehiclesDelayMillis must not be negative, was $parkIdleVehiclesDelayMillis"
        }
        require(rechargeIdleVehiclesDelayMillis >= 0) {
            "rechargeIdleVehiclesDelayMillis must not be negative, was $rechargeIdleVehiclesDelayMillis"
        }
    }
}

/**
 * The default [DispatcherConfiguration.orderCandidateWindow]. 50 rather than 10 (session 31): the nearest of 50 cut the
 * grids' empty driving by about half and their makespans by about a tenth, with fewer deadlocks on the grids and a
 * few more on the warehouse plant; the README gives the figures.
 */
const val DEFAULT_ORDER_CANDIDATE_WINDOW: Int = 50

/** Keys for ranking transport orders against each other. */
enum class OrderPriority {
    /** Oldest first. */
    BY_AGE,

    /** Earliest deadline first. */
    BY_DEADLINE,

    /** Orders whose deadline is less than the at-risk period away (or past) first. */
    DEADLINE_AT_RISK_FIRST,

    /** By name, lexicographically. */
    BY_NAME,
}

/** Keys for ranking vehicles against each other. */
enum class VehiclePriority {
    /** Vehicles in state IDLE first. */
    IDLE_FIRST,

    /** Highest energy level first. */
    BY_ENERGY_LEVEL,

    /** By name, lexicographically. */
    BY_NAME,
}

/**
 * Keys for ranking assignment candidates (a vehicle with an order and its routes).
 *
 * @property needsRoute whether the key compares route costs, so the candidates must be routed before they are ranked.
 */
enum class CandidatePriority(val needsRoute: Boolean = false) {
    /** Oldest order first. */
    BY_AGE,

    /** Earliest order deadline first. */
    BY_DEADLINE,

    /** Orders whose deadline is at risk first. */
    DEADLINE_AT_RISK_FIRST,

    /** By order name, lexicographically. */
    BY_ORDER_NAME,

    /** Vehicles in state IDLE first. */
    IDLE_FIRST,

    /** Highest vehicle energy level first. */
    BY_ENERGY_LEVEL,

    /** By vehicle name, lexicographically. */
    BY_VEHICLE_NAME,

    /** Lowest costs of the routes to all destinations first. */
    BY_COMPLETE_ROUTING_COSTS(needsRoute = true),

    /** Lowest costs of the route to the first destination first. */
    BY_INITIAL_ROUTING_COSTS(needsRoute = true),

    /** Order types the vehicle prefers (lower acceptable-order-type priority) first; `*` counts after exact names. */
    BY_ORDER_TYPE_PRIORITY,
}
