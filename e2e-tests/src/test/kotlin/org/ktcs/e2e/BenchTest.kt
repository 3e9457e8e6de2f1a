package org.ktcs.e2e

import io.kotest.core.spec.style.FunSpec
import io.kotest.matchers.collections.shouldContainAll
import io.kotest.matchers.shouldBe
import kotlin.time.Duration.Companion.seconds

/** `./ktcs bench` with tiny workloads: it starts kTCS, drives it through the web API and prints every figure. */
class BenchTest : FunSpec({
    fun figures(output: String): Map<String, String> = output.lines()
        .filter { ": " in it && !it.startsWith("ktcs bench") }
        .associate { it.substringBefore(": ") to it.substringAfter(": ") }

    test("the demo workload prints start-up, memory, CPU per order, creation rates and list latency") {
        val args =
            arrayOf("--cpu-batches", "3", "--posts", "20", "--pool", "100", "--gets", "5", "--stall-timeout", "60")
        KtcsProcess("bench", "demo", *args).use { bench ->
            bench.awaitExit(timeout = 180.seconds) shouldBe 0
            val figures = figures(bench.output())
            figures["orders_3_finished"] shouldBe "3"
            figures["get_orders_pool"] shouldBe "100"
            figures.keys shouldContainAll listOf(
                "launch_ready_s",
                "rss_ready_mib",
                "rss_end_mib",
                "kernel_cpu_per_order_3_ms",
                "kernel_thread_cpu_per_order_3_ms",
                "create_1_client_per_s",
                "create_1_client_client_cpu_s",
                "create_8_clients_per_s",
                "create_8_clients_cpu_per_post_ms",
                "create_8_clients_kernel_thread_cpu_per_post_ms",
                "post_p50_ms",
                "create_1_client_raw_per_s",
                "create_1_client_raw_client_cpu_s",
                "create_8_clients_raw_per_s",
                "post_p50_raw_ms",
                "get_orders_p50_ms",
                "get_orders_p95_ms",
                "get_orders_cpu_ms",
                "get_unknown_order_p50_ms",
                "get_unknown_order_cpu_ms",
            )
        }
    }

    test("the batch workload prints what finished, its makespan next to the lower bound and the traffic figures") {
        KtcsProcess("bench", "batch", "--orders", "8", "--stall-timeout", "60").use { bench ->
            bench.awaitExit(timeout = 180.seconds) shouldBe 0
            val figures = figures(bench.output())
            figures["orders_posted"] shouldBe "8"
            figures["orders_finished"] shouldBe "8"
            figures["double_allocations"] shouldBe "0"
            figures["shared_positions"] shouldBe "0"
            figures.keys shouldContainAll listOf(
                "kernel_cpu_per_order_ms",
                "makespan_wall_s",
                "makespan_simulated_s",
                "lower_bound_simulated_s",
                "assign_latency_p50_ms",
                "assign_latency_p99_ms",
                "deadlock_notifications",
                "idle_vehicle_notifications",
            )
        }
    }
})
