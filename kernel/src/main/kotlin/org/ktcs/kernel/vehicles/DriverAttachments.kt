package org.ktcs.kernel.vehicles

import org.ktcs.api.driver.VehicleDriverFactory
import org.ktcs.api.event.DriverEvent
import org.ktcs.api.service.DriverAttachment

/** Which drivers the vehicles have, read-only: what code outside the kernel's core may see of [VehicleControllers]. */
interface DriverAttachments {
    /** The latest driver events of [vehicle] (`null`: of all), oldest first, for clients that connect later. */
    fun recentDriverEvents(vehicle: String?): List<DriverEvent>

    fun attachment(vehicle: String): DriverAttachment

    /** The name of the driver attached to [vehicle], or null. */
    fun driverName(vehicle: String): String?

    /** The factory named [name], or `null`. */
    fun factory(name: String): VehicleDriverFactory?
}
