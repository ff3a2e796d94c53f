/* collide: the built-in task pool (see thread_pool.h). A task is cut into blocks of at least
 * minRange items; the workers and the finishing thread take blocks with an atomic counter. Which
 * thread runs which block varies; the callers' tasks are written so that the results do not
 * depend on it. */
#include "thread_pool.h"

#include "collide/collide.h"

#if defined(__EMSCRIPTEN__) || defined(__wasi__) || defined(COLLIDE_NO_THREADS)

cdThreadPool* cdThreadPool_Create(int workerCount)
{
	(void)workerCount;
	return NULL;
}

void cdThreadPool_Destroy(cdThreadPool* pool)
{
	(void)pool;
}

void* cdThreadPool_Enqueue(cdTaskCallback* task, int itemCount, int minRange, void* taskContext, void* pool)
{
	(void)minRange;
	(void)pool;
	task(0, itemCount, 0, taskContext);
	return NULL;
}

void cdThreadPool_Finish(void* userTask, void* pool)
{
	(void)userTask;
	(void)pool;
}

void* cdThreadPool_EnqueueEach(cdTaskCallback* task, int itemCount, void* taskContext, cdThreadPool* pool)
{
	(void)pool;
	task(0, itemCount, 0, taskContext);
	return NULL;
}

void cdThreadPool_Wait(int spin)
{
	(void)spin;
}

#else

#include <pthread.h>
#include <sched.h>
#include <stdatomic.h>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#include <stdlib.h>
#include <string.h>

#define CD_POOL_MAX_THREADS 64

typedef struct cdPoolWorker
{
	cdThreadPool* pool;
	uint32_t index;
} cdPoolWorker;

struct cdThreadPool
{
	pthread_mutex_t mutex;
	pthread_cond_t wake; /* a new task or the end */
	pthread_cond_t done; /* a worker left the task */
	pthread_t threads[CD_POOL_MAX_THREADS];
	cdPoolWorker workers[CD_POOL_MAX_THREADS];
	int threadCount;
	bool quit;
	/* the task in progress (written under the mutex before generation changes) */
	uint64_t generation;
	cdTaskCallback* task;
	void* taskContext;
	int itemCount, blockSize, blockCount;
	int active; /* threads working on the task, under the mutex */
	atomic_int nextBlock;
};

/* Runs blocks of the current task until none is left. */
static void cdPoolWork(cdThreadPool* pool, uint32_t workerIndex)
{
	for (;;)
	{
		int block = atomic_fetch_add(&pool->nextBlock, 1);
		if (block >= pool->blockCount)
		{
			return;
		}
		int start = block * pool->blockSize;
		int end = start + pool->blockSize < pool->itemCount ? start + pool->blockSize : pool->itemCount;
		pool->task(start, end, workerIndex, pool->taskContext);
	}
}

static void* cdPoolThread(void* arg)
{
	cdPoolWorker* worker = (cdPoolWorker*)arg;
	cdThreadPool* pool = worker->pool;
	uint64_t seen = 0;
	pthread_mutex_lock(&pool->mutex);
	for (;;)
	{
		while (!pool->quit && pool->generation == seen)
		{
			pthread_cond_wait(&pool->wake, &pool->mutex);
		}
		if (pool->quit)
		{
			break;
		}
		seen = pool->generation;
		pool->active++;
		pthread_mutex_unlock(&pool->mutex);
		cdPoolWork(pool, worker->index);
		pthread_mutex_lock(&pool->mutex);
		if (--pool->active == 0)
		{
			pthread_cond_broadcast(&pool->done);
		}
	}
	pthread_mutex_unlock(&pool->mutex);
	return NULL;
}

cdThreadPool* cdThreadPool_Create(int workerCount)
{
	if (workerCount < 2)
	{
		return NULL;
	}
	cdThreadPool* pool = (cdThreadPool*)cdAlloc(sizeof(cdThreadPool));
	if (pool == NULL)
	{
		return NULL;
	}
	memset(pool, 0, sizeof(*pool));
	if (pthread_mutex_init(&pool->mutex, NULL) != 0)
	{
		cdFree(pool);
		return NULL;
	}
	if (pthread_cond_init(&pool->wake, NULL) != 0 || pthread_cond_init(&pool->done, NULL) != 0)
	{
		/* Destroying a condition that failed to initialise is undefined: keep it simple and leak
		 * nothing else. */
		pthread_mutex_destroy(&pool->mutex);
		cdFree(pool);
		return NULL;
	}
	atomic_init(&pool->nextBlock, 0);
	int threads = workerCount - 1 < CD_POOL_MAX_THREADS ? workerCount - 1 : CD_POOL_MAX_THREADS;
	for (int i = 0; i < threads; ++i)
	{
		pool->workers[i].pool = pool;
		pool->workers[i].index = (uint32_t)(i + 1);
		if (pthread_create(pool->threads + i, NULL, cdPoolThread, pool->workers + i) != 0)
		{
			break;
		}
		pool->threadCount++;
	}
	if (pool->threadCount == 0)
	{
		cdThreadPool_Destroy(pool);
		return NULL;
	}
	return pool;
}

void cdThreadPool_Destroy(cdThreadPool* pool)
{
	if (pool == NULL)
	{
		return;
	}
	pthread_mutex_lock(&pool->mutex);
	pool->quit = true;
	pthread_cond_broadcast(&pool->wake);
	pthread_mutex_unlock(&pool->mutex);
	for (int i = 0; i < pool->threadCount; ++i)
	{
		pthread_join(pool->threads[i], NULL);
	}
	pthread_cond_destroy(&pool->wake);
	pthread_cond_destroy(&pool->done);
	pthread_mutex_destroy(&pool->mutex);
	cdFree(pool);
}

/* Publishes the task (blocks of blockSize items) and wakes the threads. */
static void* cdPoolStart(cdThreadPool* pool, cdTaskCallback* task, int itemCount, int blockSize,
						 void* taskContext)
{
	pthread_mutex_lock(&pool->mutex);
	/* A thread that woke late for the last task may still be looking at it. */
	while (pool->active > 0)
	{
		pthread_cond_wait(&pool->done, &pool->mutex);
	}
	pool->task = task;
	pool->taskContext = taskContext;
	pool->itemCount = itemCount;
	pool->blockSize = blockSize;
	pool->blockCount = (itemCount + blockSize - 1) / blockSize;
	atomic_store(&pool->nextBlock, 0);
	pool->generation++;
	pthread_cond_broadcast(&pool->wake);
	pthread_mutex_unlock(&pool->mutex);
	return pool;
}

void* cdThreadPool_Enqueue(cdTaskCallback* task, int itemCount, int minRange, void* taskContext,
						   void* userContext)
{
	cdThreadPool* pool = (cdThreadPool*)userContext;
	if (itemCount <= 0)
	{
		return NULL;
	}
	int workers = pool->threadCount + 1;
	int blockSize = minRange > 1 ? minRange : 1;
	/* A few blocks per worker, so that a slow thread does not hold the others up. */
	int even = (itemCount + 4 * workers - 1) / (4 * workers);
	if (even > blockSize)
	{
		blockSize = even;
	}
	if (blockSize >= itemCount)
	{
		task(0, itemCount, 0, taskContext);
		return NULL;
	}
	return cdPoolStart(pool, task, itemCount, blockSize, taskContext);
}

void* cdThreadPool_EnqueueEach(cdTaskCallback* task, int itemCount, void* taskContext, cdThreadPool* pool)
{
	if (itemCount <= 0)
	{
		return NULL;
	}
	return cdPoolStart(pool, task, itemCount, 1, taskContext);
}

void cdThreadPool_Wait(int spin)
{
	if (spin < 64)
	{
#if defined(__SSE2__)
		for (int i = 0; i < 8; ++i)
		{
			_mm_pause();
		}
#endif
		return;
	}
	sched_yield();
}

void cdThreadPool_Finish(void* userTask, void* userContext)
{
	(void)userContext;
	cdThreadPool* pool = (cdThreadPool*)userTask;
	if (pool == NULL)
	{
		return;
	}
	/* Once this thread finds no block left, every block has been taken: by it (done) or by a
	 * thread counted in active until it has finished its blocks. */
	cdPoolWork(pool, 0);
	pthread_mutex_lock(&pool->mutex);
	while (pool->active > 0)
	{
		pthread_cond_wait(&pool->done, &pool->mutex);
	}
	pthread_mutex_unlock(&pool->mutex);
}

#endif
