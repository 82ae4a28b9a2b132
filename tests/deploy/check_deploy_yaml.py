#!/usr/bin/python3
"""deploy/'s YAML parses and says what deploy/README.md says it does.

compose.yaml, envoy/envoy.yaml and every k8s/*.yaml are loaded with yaml.safe_load_all
(Debian's python3-yaml), then checked for the properties the deployment relies on:
two servers on a shared PostgreSQL store behind a load balancer that hashes on
x-relmap-session, gRPC health probes, resources sized, the Secret behind RELMAP_STORE.
Neither Docker nor Kubernetes runs here: this is what can be checked without them.
    check_deploy_yaml.py <repository root>
"""
import pathlib
import shutil
import subprocess
import sys

import yaml

failures = []


def check(name, condition):
    print(("ok   " if condition else "FAIL ") + name)
    if not condition:
        failures.append(name)


def load_all(path):
    with open(path, encoding="utf-8") as stream:
        return [doc for doc in yaml.safe_load_all(stream) if doc is not None]


def containers(workload):
    return workload["spec"]["template"]["spec"]["containers"]


def check_compose(deploy):
    (compose,) = load_all(deploy / "compose.yaml")
    services = compose["services"]
    servers = {name: s for name, s in services.items() if name.startswith("relmap-server")}
    check("compose: two relmap-servers", len(servers) == 2)
    for name, server in servers.items():
        store = str(server.get("environment", {}).get("RELMAP_STORE", ""))
        check(f"compose: {name} stores in postgres", store.startswith("postgres://"))
        check(f"compose: {name} waits for postgres",
              server.get("depends_on", {}).get("postgres", {}).get("condition") == "service_healthy")
        check(f"compose: {name} builds deploy/Dockerfile",
              server.get("build", {}).get("dockerfile") == "deploy/Dockerfile")
    check("compose: postgres", services.get("postgres", {}).get("image", "").startswith("postgres:"))
    nginx = services.get("nginx", {})
    mounts = [str(v).split(":")[0] for v in nginx.get("volumes", [])]
    check("compose: nginx mounts deploy/nginx/compose.conf", "./nginx/compose.conf" in mounts
          and (deploy / "nginx" / "compose.conf").is_file())
    sim = services.get("relmap-sim", {})
    command = sim.get("command", [])
    check("compose: relmap-sim runs through nginx",
          sim.get("entrypoint") == ["relmap-sim"] and "nginx:8080" in command)
    check("compose: nginx listens where relmap-sim calls",
          any(str(p).endswith(":8080") for p in nginx.get("ports", [])))


def check_envoy(deploy):
    (envoy,) = load_all(deploy / "envoy" / "envoy.yaml")
    resources = envoy["static_resources"]
    (listener,) = resources["listeners"]
    (manager,) = listener["filter_chains"][0]["filters"]
    config = manager["typed_config"]
    check("envoy: HTTP/2 listener", config.get("codec_type") == "HTTP2"
          and "http2_protocol_options" in config)
    routes = [r for vh in config["route_config"]["virtual_hosts"] for r in vh["routes"]]
    hashed = [h.get("header", {}).get("header_name") for r in routes
              for h in r["route"].get("hash_policy", [])]
    check("envoy: routes hash on x-relmap-session", hashed == ["x-relmap-session"] * len(routes))
    clusters = {c["name"]: c for c in resources["clusters"]}
    targets = {r["route"]["cluster"] for r in routes}
    check("envoy: routes go to defined clusters", targets <= set(clusters))
    for name in targets:
        cluster = clusters[name]
        check(f"envoy: {name} is RING_HASH", cluster.get("lb_policy") == "RING_HASH")
        check(f"envoy: {name} has gRPC health checks",
              any("grpc_health_check" in h for h in cluster.get("health_checks", [])))
        check(f"envoy: {name} never panics onto unhealthy servers",
              cluster.get("common_lb_config", {}).get("healthy_panic_threshold") == {"value": 0})
        options = cluster.get("typed_extension_protocol_options", {}).get(
            "envoy.extensions.upstreams.http.v3.HttpProtocolOptions", {})
        check(f"envoy: {name} speaks HTTP/2 upstream",
              "http2_protocol_options" in options.get("explicit_http_config", {}))
        endpoints = [e for group in cluster["load_assignment"]["endpoints"]
                     for e in group["lb_endpoints"]]
        check(f"envoy: {name} has two servers", len(endpoints) == 2)


def check_k8s(deploy):
    directory = deploy / "k8s"
    documents = {}
    for path in sorted(directory.glob("*.yaml")):
        try:
            documents[path.name] = load_all(path)
        except yaml.YAMLError as error:
            check(f"k8s: {path.name} parses ({error})", False)
    check("k8s: manifests found", len(documents) >= 5)

    (kustomization,) = documents.pop("kustomization.yaml")
    listed = set(kustomization["resources"])
    check("k8s: kustomization resources exist", listed <= set(documents))
    check("k8s: every manifest but the Job is in the kustomization",
          set(documents) - listed == {"relmap-sim-job.yaml"})
    for generator in kustomization.get("configMapGenerator", []):
        for file in generator.get("files", []):
            check(f"k8s: configMapGenerator file {file} exists",
                  (directory / file.split("=")[-1]).is_file())

    objects = [doc for docs in documents.values() for doc in docs]
    by_kind = {}
    for doc in objects:
        check(f"k8s: {doc.get('kind')} {doc.get('metadata', {}).get('name')} has apiVersion",
              "apiVersion" in doc)
        by_kind.setdefault(doc["kind"], {})[doc["metadata"]["name"]] = doc

    workloads = {**by_kind.get("Deployment", {}), **by_kind.get("StatefulSet", {})}
    for name, workload in workloads.items():
        for container in containers(workload):
            what = f"k8s: {name}/{container['name']}"
            check(f"{what} has readiness and liveness probes",
                  "readinessProbe" in container and "livenessProbe" in container)
            check(f"{what} requests cpu and memory",
                  {"cpu", "memory"} <= set(container.get("resources", {}).get("requests", {})))
            check(f"{what} limits memory", "memory" in container.get("resources", {}).get("limits", {}))

    server = workloads.get("relmap-server")
    check("k8s: relmap-server StatefulSet", server is not None and server["kind"] == "StatefulSet")
    if server is None:
        return
    (container,) = containers(server)
    for probe in ("startupProbe", "readinessProbe", "livenessProbe"):
        check(f"k8s: relmap-server {probe} is gRPC on the server's port",
              container.get(probe, {}).get("grpc", {}).get("port") == 50051)
    service = by_kind.get("Service", {}).get(server["spec"]["serviceName"], {})
    check("k8s: relmap-server's service is headless", service.get("spec", {}).get("clusterIP") == "None")
    env = {e["name"]: e for e in container.get("env", [])}
    secret_ref = env.get("RELMAP_STORE", {}).get("valueFrom", {}).get("secretKeyRef", {})
    secret = by_kind.get("Secret", {}).get(secret_ref.get("name"), {})
    check("k8s: RELMAP_STORE comes from a Secret that has the key",
          secret_ref.get("key") in secret.get("stringData", {}))
    check("k8s: the Secret's URI is PostgreSQL",
          str(secret.get("stringData", {}).get(secret_ref.get("key"), "")).startswith("postgres://"))
    grace = server["spec"]["template"]["spec"].get("terminationGracePeriodSeconds", 30)
    drain = int(env.get("RELMAP_DRAIN_SECONDS", {}).get("value", 0))
    check("k8s: the grace period covers the drain and 10 s of calls", grace >= drain + 10)

    nginx_conf = (directory / "nginx.conf").read_text(encoding="utf-8")
    replicas = server["spec"]["replicas"]
    namespace = kustomization.get("namespace", "default")
    names = [f"relmap-server-{i}.{service['metadata']['name']}.{namespace}.svc.cluster.local:50051"
             for i in range(replicas)]
    check("k8s: nginx.conf has one server per replica, by its stable name",
          all(f"server {n} " in nginx_conf for n in names)
          and nginx_conf.count("\n        server ") == replicas)


def check_kustomize(deploy):
    """kubectl kustomize builds the kustomization offline, where kubectl is installed."""
    if shutil.which("kubectl") is None:
        print("skip k8s: kubectl kustomize (no kubectl)")
        return
    built = subprocess.run(["kubectl", "kustomize", str(deploy / "k8s")], capture_output=True,
                           text=True, check=False)
    check("k8s: kubectl kustomize builds it " + built.stderr.strip(), built.returncode == 0)
    if built.returncode != 0:
        return
    objects = [doc for doc in yaml.safe_load_all(built.stdout) if doc is not None]
    maps = [o["metadata"]["name"] for o in objects if o["kind"] == "ConfigMap"]
    nginx = [o for o in objects if o["kind"] == "Deployment" and o["metadata"]["name"] == "relmap-nginx"]
    volumes = nginx[0]["spec"]["template"]["spec"]["volumes"] if nginx else []
    check("k8s: nginx mounts the generated ConfigMap",
          any(v.get("configMap", {}).get("name") in maps for v in volumes))
    check("k8s: everything in the relmap namespace",
          all(o["metadata"].get("namespace") == "relmap" or o["kind"] == "Namespace"
              for o in objects))


def main():
    deploy = pathlib.Path(sys.argv[1]) / "deploy"
    check_compose(deploy)
    check_envoy(deploy)
    check_k8s(deploy)
    check_kustomize(deploy)
    print(f"{len(failures)} failed" if failures else "all passed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
