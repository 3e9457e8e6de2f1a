package org.ktcs.kernel.core

import org.koin.core.module.Module
import org.koin.dsl.bind
import org.koin.dsl.module
import org.ktcs.api.driver.DriverContext
import org.ktcs.api.driver.VehicleDriver
import org.ktcs.api.driver.VehicleDriverFactory

/** [StepDriver]s that keep each vehicle's [DriverContext], so a test can report for a vehicle as its driver would. */
class RecordingStepDrivers {
    val contexts = mutableMapOf<String, DriverContext>()

    val module: Module = driverModule("step", "test vehicle that drives at 1 m/s") { vehicleName, context ->
        StepDriver(vehicleName, context).also { contexts[vehicleName] = context }
    }
}

/** A Koin module with one test driver factory, [name], whose drivers [create] makes. */
fun driverModule(
    name: String,
    description: String,
    create: (vehicleName: String, context: DriverContext) -> VehicleDriver,
): Module = module {
    single {
        object : VehicleDriverFactory {
            override val name = name
            override val description = description

            override fun create(vehicleName: String, context: DriverContext): VehicleDriver = create(
                vehicleName,
                context,
            )
        }
    } bind VehicleDriverFactory::class
}
