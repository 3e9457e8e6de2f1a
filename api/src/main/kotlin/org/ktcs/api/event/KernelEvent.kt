package org.ktcs.api.event

import org.ktcs.api.model.Location
import org.ktcs.api.model.Path
import org.ktcs.api.model.PlantModel
import org.ktcs.api.model.Point
import org.ktcs.api.model.Vehicle
import org.ktcs.api.order.OrderSequence
import org.ktcs.api.order.TransportOrder
import java.time.Instant

/** Something that happened in the kernel, published in the order it happened. */
public sealed interface KernelEvent

/** An object was created ([previous] is `null`), changed, or removed ([current] is `null`). */
public sealed interface ObjectEvent<T : Any> : KernelEvent {
    /** The object before the change, `null` if it was created. */
    public val previous: T?

    /** The object after the change, `null` if it was removed. */
    public val current: T?

    /** What kind of change this is. */
    public val change: Change
        get() = when {
            previous == null -> Change.CREATED
            current == null -> Change.REMOVED
            else -> Change.MODIFIED
        }

    /** The kinds of change, with openTCS's names in the web API. */
    public enum class Change { CREATED, MODIFIED, REMOVED }
}

/** A transport order changed. */
public data class TransportOrderEvent(override val previous: TransportOrder?, override val current: TransportOrder?) :
    ObjectEvent<TransportOrder>

/** An order sequence changed. */
public data class OrderSequenceEvent(override val previous: OrderSequence?, override val current: OrderSequence?) :
    ObjectEvent<OrderSequence>

/** A vehicle changed. */
public data class VehicleEvent(override val previous: Vehicle?, override val current: Vehicle?) : ObjectEvent<Vehicle>

/** A point changed. */
public data class PointEvent(override val previous: Point?, override val current: Point?) : ObjectEvent<Point>

/** A path changed, e.g. it was locked. */
public data class PathEvent(override val previous: Path?, override val current: Path?) : ObjectEvent<Path>

/** A location changed, e.g. it was locked. */
public data class LocationEvent(
    override val previous: Location?,
    override val current: Location?,
) : ObjectEvent<Location>

/** The whole plant model was replaced; every earlier object is gone. */
public data class PlantModelReplacedEvent(val model: PlantModel) : KernelEvent

/** A message for the operators. */
public data class UserNotificationEvent(val notification: UserNotification) : KernelEvent

/**
 * An event a vehicle driver published with [org.ktcs.api.driver.DriverContext.publishEvent]: [type] names it (prefix
 * it with the driver's name, e.g. `loopback:commandFinished`), [payload] holds a few strings, [timestamp] is the
 * kernel's time. Web clients get it on the WebSocket topic `driverEvents`, the SSE stream and
 * `GET /v1/vehicles/{name}/driverEvents`.
 */
public data class DriverEvent(
    val vehicle: String,
    val type: String,
    val payload: Map<String, String>,
    val timestamp: Instant,
) :
    KernelEvent

/**
 * A message for the operators.
 *
 * @property source who sent it (a vehicle, a kernel component), `null` if unknown.
 */
public data class UserNotification(
    val source: String?,
    val text: String,
    val level: NotificationLevel,
    val timestamp: Instant,
)

/** How important a user notification is, with openTCS's names. */
public enum class NotificationLevel { INFORMATIONAL, NOTEWORTHY, IMPORTANT }
