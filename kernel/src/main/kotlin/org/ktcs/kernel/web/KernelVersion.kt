package org.ktcs.kernel.web

import java.util.Properties

/** The version of this kTCS build, written into the jar by Maven. */
data class KernelVersion(val version: String) {
    companion object {
        fun ofThisBuild(): KernelVersion {
            val properties = Properties()
            KernelVersion::class.java.getResourceAsStream("/org/ktcs/kernel/version.properties")?.use(properties::load)
            return KernelVersion(properties.getProperty("version") ?: "unknown")
        }
    }
}
