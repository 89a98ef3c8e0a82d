//! The pipelines of the frame recipe's passes, each owned by its pass
//! (`passes::*`), built once per renderer and held here together.

use std::sync::Arc;

use crate::Result;
use crate::features::Features;
use crate::passes::accumulate::AccumulatePipeline;
use crate::passes::bloom::BloomPipelines;
use crate::passes::composite::CompositePipelines;
use crate::passes::exposure::ExposurePipeline;
use crate::passes::polarimetry::PolarimetryPipelines;
use crate::passes::raymarch::RaymarchPipelines;
use crate::vk::Gpu;

/// Every pass's pipelines.
pub struct Pipelines {
    pub raymarch: RaymarchPipelines,
    pub accumulate: AccumulatePipeline,
    pub bloom: BloomPipelines,
    pub exposure: ExposurePipeline,
    pub composite: CompositePipelines,
    pub polarimetry: PolarimetryPipelines,
}

impl Pipelines {
    /// Builds them on `gpu` for what the renderer does there.
    pub fn new(gpu: &Arc<Gpu>, features: Features) -> Result<Self> {
        Ok(Pipelines {
            raymarch: RaymarchPipelines::new(gpu, features)?,
            accumulate: AccumulatePipeline::new(gpu)?,
            bloom: BloomPipelines::new(gpu)?,
            exposure: ExposurePipeline::new(gpu)?,
            composite: CompositePipelines::new(gpu)?,
            polarimetry: PolarimetryPipelines::new(gpu)?,
        })
    }

    /// What the renderer does on this device.
    pub fn features(&self) -> Features {
        self.raymarch.features()
    }
}
