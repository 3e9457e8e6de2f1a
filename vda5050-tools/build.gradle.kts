plugins {
    id("ktcs.kotlin-jvm")
}

dependencies {
    implementation(project(":kernel"))
    implementation(project(":adapters-vda5050"))
}
