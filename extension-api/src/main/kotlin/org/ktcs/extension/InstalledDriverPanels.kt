package org.ktcs.extension

import org.ktcs.api.driver.DriverPanel

/** The panels of the installed vehicle drivers, by driver name. Bound by the kernel. */
public fun interface InstalledDriverPanels {
    /** The panel of the driver named [driver], or `null` if it has none or no such driver is installed. */
    public fun of(driver: String): DriverPanel?
}
