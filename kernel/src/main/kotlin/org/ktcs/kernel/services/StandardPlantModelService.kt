package org.ktcs.kernel.services

import org.ktcs.api.model.PlantModel
import org.ktcs.api.service.PlantModelService
import org.ktcs.kernel.core.KernelCore
import org.ktcs.kernel.store.durably

class StandardPlantModelService(private val kernel: KernelCore) : PlantModelService {
    override suspend fun plantModel(): PlantModel = kernel.context.call { kernel.plant.model() }

    override suspend fun setPathLocked(path: String, locked: Boolean) = kernel.durably {
        kernel.setPathLocked(path, locked)
    }

    override suspend fun setLocationLocked(location: String, locked: Boolean) =
        kernel.durably { kernel.requests.setLocationLocked(location, locked) }

    override suspend fun replacePlantModel(model: PlantModel) = kernel.durably {
        kernel.replacePlantModel(model)
    }

    override suspend fun updateRoutingTopology() = kernel.context.call {
        kernel.router.updateTopology(kernel.plant.layoutWithLocks())
    }
}
