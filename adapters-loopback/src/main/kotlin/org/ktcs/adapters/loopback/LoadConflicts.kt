package org.ktcs.adapters.loopback

import org.ktcs.api.kernel.Explained

/** Whether a sequence of operations fits the vehicle's load state, with openTCS's reason names. */
internal object LoadConflicts {
    const val CANNOT_LOAD_WHEN_LOADED: String = "cannotLoadWhenLoaded"
    const val CANNOT_UNLOAD_WHEN_NOT_LOADED: String = "cannotUnloadWhenNotLoaded"

    /** Plays [operations] from the load state [loaded]: a load needs an empty vehicle, an unload a full one. */
    fun check(operations: List<String>, loaded: Boolean, parameters: VehicleParameters): Explained {
        var full = loaded
        for (operation in operations) {
            when (operation) {
                parameters.loadOperation -> if (full) return Explained.no(CANNOT_LOAD_WHEN_LOADED) else full = true

                parameters.unloadOperation -> if (!full) {
                    return Explained.no(CANNOT_UNLOAD_WHEN_NOT_LOADED)
                } else {
                    full =
                        false
                }
            }
        }
        return Explained.YES
    }
}
