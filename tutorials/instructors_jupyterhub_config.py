# jupyterhub_config.py for a course on one machine (JupyterHub 5 or newer; tutorials/instructors_jupyterhub.md,
# "A hub on one machine"). Copy it to /etc/jupyterhub/jupyterhub_config.py, change what is marked CHANGE, and start
# `/opt/course/bin/jupyterhub -f /etc/jupyterhub/jupyterhub_config.py` as root (each student's server runs as them).
# Not part of the students' handout (make handout leaves tutorials/instructors* out).

c = get_config()  # noqa: F821  (JupyterHub defines get_config when it reads this file)

# Where students log in. Serve the hub behind HTTPS (a reverse proxy such as Caddy or nginx in front of this port).
c.JupyterHub.bind_url = "http://127.0.0.1:8000"
c.JupyterHub.public_url = "https://hub.example.edu/"  # CHANGE: the address students open; the viewer prints whole
# addresses with it (JupyterHub passes it to each server as JUPYTERHUB_PUBLIC_URL)

# Who may log in: the class's Unix accounts (PAM, JupyterHub's default authenticator).
c.Authenticator.allowed_users = {"ana", "ben"}  # CHANGE, or c.Authenticator.allow_all = True for every account

# Each student's server: JupyterLab from the course's environment (the toolkit, jupyter-server-proxy, nbgitpuller),
# run as the student (the default LocalProcessSpawner; SystemdSpawner also enforces the limits below).
c.Spawner.cmd = ["/opt/course/bin/jupyterhub-singleuser"]  # /opt/course: the guide's one install command made it
c.Spawner.default_url = "/lab"
c.Spawner.environment = {
    "TOOLKIT_QUICK": "1",  # the chapters at their quick sizes (about a minute each on one core); "0": full size
    "TOOLKIT_CACHE": "/srv/course/models",  # the class's trained models, filled once by the instructor, read-only
}
c.Spawner.mem_limit = "3G"  # two chapters open and a viewer: about 2 GB (the guide's measurements)
c.Spawner.cpu_limit = 1.0
