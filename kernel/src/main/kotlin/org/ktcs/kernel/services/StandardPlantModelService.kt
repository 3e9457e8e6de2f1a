package org.ktcs.kernel.services

import org.ktcs.api.model.PlantModel
import org.ktcs.api.service.PlantModelService
import org.ktcs.kernel.core.KernelCore
import org.ktcs.kernel.persistence.PublishedModelFile
import org.ktcs.kernel.store.durably

/** The plant-model service; a model that replaces the plant is first saved to [published] (when given). */
class StandardPlantModelService(
    private val kernel: KernelCore,
    private val published: PublishedModelFile? = null,
) : PlantModelService {
    override suspend fun plantModel(): PlantModel = kernel.context.call { kernel.plant.model() }

    override suspend fun setPathLocked(path: String, locked: Boolean) = kernel.durably {
        kernel.setPathLocked(path, locked)
    }

    override suspend fun setLocationLocked(location: String, locked: Boolean) =
        kernel.durably { kernel.requests.setLocationLocked(location, locked) }

    override suspend fun replacePlantModel(model: PlantModel) = kernel.durably {
        // Saved on the kernel's thread: publishing is rare, and no other change may slip in between save and apply.
        kernel.replacePlantModel(model) { published?.save(it) }
    }

    override suspend fun updateRoutingTopology() = kernel.context.call { kernel.updateRoutingTopology() }
}
